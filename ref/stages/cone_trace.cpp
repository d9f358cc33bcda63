#include "stages/cone_trace.h"

#include <algorithm>
#include <cmath>

#include "shared/vct_shared.h"
#include "stages/march_schedule.h"
#include "stages/mip_sampler.h"
#include "stages/voxel_sampler.h"

namespace vct {

MarchParams MarchParams::from_settings(const VctSettings& s, int grid) {
  MarchParams p;
  const float offset = s.cone_offset_voxels / float(grid);
  // Both conventions put the first sample cone_offset_voxels from the surface along the normal
  // cone; they differ for tilted cones (axis: offset x cos(tilt) above the surface) and in the
  // first sample's diameter (axis: 2 t tan(aperture/2); normal: one voxel, t = 0).
  // The normal start may also skip cone_axis_offset_voxels along the axis (the source design's
  // ConeTracing offset after its normal offset; validate_settings keeps it 0 under axis).
  if (s.cone_start == ConeStart::Normal) {
    p.normal_offset = offset;
    p.start_offset = s.cone_axis_offset_voxels / float(grid);
  } else {
    p.start_offset = offset;
  }
  p.max_distance = s.max_distance;
  p.quality = s.cone_quality;
  p.step_correction = s.opacity_step_correction;
  return p;
}

MarchParams MarchParams::specular_from_settings(const VctSettings& s, int grid) {
  MarchParams p = from_settings(s, grid);
  if (s.specular_offset_voxels >= 0.0f) {
    const float offset = s.specular_offset_voxels / float(grid);
    p.normal_offset = s.cone_start == ConeStart::Normal ? offset : 0.0f;
    p.start_offset = s.cone_start == ConeStart::Normal ? 0.0f : offset;
  }
  if (s.specular_quality > 0.0f) p.quality = s.specular_quality;
  return p;
}

MarchParams MarchParams::shadow_from_settings(const VctSettings& s, int grid) {
  MarchParams p = from_settings(s, grid);
  p.start_offset = s.cone_offset_voxels / float(grid);
  p.normal_offset = 0.0f;
  return p;
}

namespace {
bool inside_unit_cube(const vec3& p) {
  return p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f && p.x <= 1.0f && p.y <= 1.0f && p.z <= 1.0f;
}

// The march itself, for either sampler (voxel_sampler.h or the frame's MipSampler, which agree
// bit for bit): one loop, so the two entry points cannot drift apart.
// A `schedule` that fits the cone gives its first steps' geometry (march_schedule.h: the same
// recurrence, computed once per frame).
template <class Sample>
vec4 march(const Cone& cone, const MarchParams& params, float voxel, const Sample& sample,
           std::vector<ConeSample>* record, const MarchSchedule* schedule = nullptr) {
  const size_t scheduled = schedule && schedule->fits(cone.aperture, params, voxel) ? schedule->size() : 0;
  const float tan_half = std::tan(0.5f * cone.aperture);
  vec3 color(0.0f);
  float alpha = 0.0f;
  float t = params.start_offset;
  for (size_t k = 0; alpha < 1.0f && t < params.max_distance; ++k) {
    const vec3 pos = cone.origin + cone.direction * t;
    if (!inside_unit_cube(pos)) break;
    const MarchStep g = k < scheduled ? (*schedule)[k] : march_step(t, tan_half, voxel, params);
    const float diameter = g.diameter, lod = g.lod, step = g.step;
    vec4 s = sample(pos, lod, cone.direction);
    // dt0: the side of a voxel of the level sampled (lod as computed, before any clamp).
    if (params.step_correction) s = sh::step_corrected_sample(s, step / (voxel * std::exp2(lod)));
    const float transmit = 1.0f - alpha;
    color += transmit * vec3(s);
    alpha += transmit * s.a;
    if (record) record->push_back({pos, t, diameter, lod, s, vec4(color, alpha)});
    t += step;
  }
  return vec4(color, std::min(alpha, 1.0f));
}

}  // namespace

vec4 trace_cone(const VoxelMips& mips, const Cone& cone, const MarchParams& params,
                std::vector<ConeSample>* record) {
  if (mips.iso.empty() || mips.iso[0].nx == 0) return vec4(0.0f);
  const auto sample = [&mips](const vec3& pos, float lod, const vec3& dir) { return sample_voxels(mips, pos, lod, dir); };
  return march(cone, params, 1.0f / float(mips.iso[0].nx), sample, record);
}

vec4 trace_cone(const MipSampler& mips, const Cone& cone, const MarchParams& params, const MarchSchedule* schedule) {
  if (mips.base_size() == 0) return vec4(0.0f);
  const auto sample = [&mips](const vec3& pos, float lod, const vec3& dir) { return mips.sample(pos, lod, dir); };
  return march(cone, params, 1.0f / float(mips.base_size()), sample, nullptr, schedule);
}

}  // namespace vct
