// A cone's march steps depend on its aperture and MarchParams alone (docs/pipeline.md, "Cone
// marching"): from t = start_offset, diameter = max(voxel, 2 t tan(aperture / 2)), lod =
// max(log2(diameter / voxel), min_lod), step = max(diameter x quality, 1e-6), t += step — not on
// the cone's origin or direction. Every diffuse cone of a frame (one aperture) walks the same t
// sequence until it stops, so a frame computes it once (issue 16) and the march reads it instead
// of a tan, a log2 and three max per step. march_step() is the one statement of the recurrence:
// the march (cone_trace.cpp) and the schedule both call it, so they give the same floats.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "stages/cone_trace.h"

namespace vct {

/// One step's geometry at distance t along a cone.
struct MarchStep {
  float diameter = 0.0f;
  float lod = 0.0f;
  float step = 0.0f;
};

inline MarchStep march_step(float t, float tan_half, float voxel, const MarchParams& params) {
  MarchStep s;
  s.diameter = std::max(voxel, 2.0f * t * tan_half);
  s.lod = std::max(std::log2(s.diameter / voxel), params.min_lod);
  // A degenerate step (quality 0) would never end; the settings validator forbids it, but a
  // hand-built MarchParams might not.
  s.step = std::max(s.diameter * params.quality, 1e-6f);
  return s;
}

class MarchSchedule {
 public:
  /// Longer marches (tiny apertures at tiny quality) compute their later steps as they go.
  static constexpr size_t kMaxSteps = size_t(1) << 16;

  MarchSchedule() = default;
  /// The steps of a cone of full aperture `aperture` (radians) under `params` on a grid of voxel
  /// side `voxel`, while t < params.max_distance (at most kMaxSteps).
  MarchSchedule(float aperture, const MarchParams& params, float voxel);

  /// True when a cone of this aperture under these params marches exactly these steps: the same
  /// aperture, start, quality, min_lod and voxel (a shorter max_distance only stops it earlier; a
  /// longer one computes the steps past the schedule).
  bool fits(float aperture, const MarchParams& params, float voxel) const {
    return !steps_.empty() && aperture == aperture_ && params.start_offset == start_offset_ &&
           params.quality == quality_ && params.min_lod == min_lod_ && voxel == voxel_;
  }
  size_t size() const { return steps_.size(); }
  const MarchStep& operator[](size_t k) const { return steps_[k]; }

 private:
  float aperture_ = 0.0f, start_offset_ = 0.0f, quality_ = 0.0f, min_lod_ = 0.0f, voxel_ = 0.0f;
  std::vector<MarchStep> steps_;
};

}  // namespace vct
