#include "stages/cone_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

float march_end_margin(float t, double drift, int tan_steps) {
  constexpr double kU = 1.0 / 16777216.0;
  return tan_steps == 0 ? 0.0f : float(double(t) * (drift + double(tan_steps + 2) * kU));
}

double march_end_step_drift(float aperture, float t, float step) {
  constexpr double kU = 1.0 / 16777216.0, kTrig = 1.0 / 2048.0;
  const double h = 0.5 * double(aperture), sh = std::sin(h), ch = std::cos(h);
  if (sh <= 0.0 || ch <= 0.0) return 1.0;
  const double eps = kTrig * (1.0 / sh + 1.0 / ch) + kTrig * h / (sh * ch) + 3.0 * kU;
  return eps * double(step) / double(t + step);
}

namespace {
bool inside_unit_cube(const vec3& p) {
  return p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f && p.x <= 1.0f && p.y <= 1.0f && p.z <= 1.0f;
}

// The march-end variants (MarchParams::march_end): whether a sample at `pos` is where a correct
// GL, whose position may lie `margin` further or nearer along `dir`, may already have left the
// volume through a face the cone leaves by (-1: stop here), and the in-volume point a GL whose
// sample fell just inside samples (+1: `pos` clamped to the cube, when it lies within the margin
// outside those faces only). Faces behind the cone count only at the first sample and only by the
// cone's origin_margin (start_face_variant): a cone starting on a wall of the volume from the
// same floats as GL's is not cut short.
// Along one axis: the distance's margin, the origin's, plus two roundings of origin + dir * t
// where the positions differ at all (both margins 0: both sides' positions are the same floats).
float axis_margin(float pos, float dir, float margin, float origin_margin) {
  return margin > 0.0f || origin_margin > 0.0f
             ? std::abs(dir) * margin + origin_margin + 2.0f * std::numeric_limits<float>::epsilon() * std::abs(pos)
             : 0.0f;
}

bool near_exit_face(const vec3& pos, const vec3& dir, float margin, const vec3& origin_margin) {
  for (int i = 0; i < 3; ++i) {
    const float m = axis_margin(pos[i], dir[i], margin, origin_margin[i]);
    if ((dir[i] > 0.0f && 1.0f - pos[i] <= m) || (dir[i] < 0.0f && pos[i] <= m)) return true;
  }
  return false;
}

bool just_past_exit_face(const vec3& pos, const vec3& dir, float margin, const vec3& origin_margin, vec3& clamped) {
  clamped = pos;
  for (int i = 0; i < 3; ++i) {
    const float m = axis_margin(pos[i], dir[i], margin, origin_margin[i]);
    if (pos[i] > 1.0f) {
      if (!(dir[i] > 0.0f && pos[i] - 1.0f <= m)) return false;
      clamped[i] = 1.0f;
    } else if (pos[i] < 0.0f) {
      if (!(dir[i] < 0.0f && -pos[i] <= m)) return false;
      clamped[i] = 0.0f;
    }
  }
  return true;
}

// The start-face tie (docs/compare.md): the first sample `pos` of a cone whose origin a correct
// GL may place `origin_margin` away per axis, against every face, behind the cone or not. -1:
// true when it lies inside within the margin of a face (GL's may lie outside: its loop breaks at
// once, the cone gives nothing). +1: true when it lies outside within the margin of each face it
// is past (GL's may lie on the face: `shift` moves ours there, and every later sample with it).
bool start_face_variant(int variant, const vec3& pos, const vec3& origin_margin, vec3& shift) {
  shift = vec3(0.0f);
  bool near = false;
  for (int i = 0; i < 3; ++i) {
    const float m = axis_margin(pos[i], 0.0f, 0.0f, origin_margin[i]);
    if (variant < 0) {
      near = near || (pos[i] >= 0.0f && pos[i] <= m) || (pos[i] <= 1.0f && 1.0f - pos[i] <= m);
    } else if (pos[i] < 0.0f || pos[i] > 1.0f) {
      const float face = pos[i] < 0.0f ? 0.0f : 1.0f;
      if (!(std::abs(pos[i] - face) <= m)) return false;
      shift[i] = face - pos[i];
      near = true;
    }
  }
  return near;
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
  double drift = 0.0;  // the march-end variants' relative drift of a correct GL's t (march_end_step_drift)
  int tan_steps = 0;
  vec3 origin = cone.origin;
  const vec3& om = cone.origin_margin;
  const bool start_tie = params.march_end != 0 && (om.x > 0.0f || om.y > 0.0f || om.z > 0.0f);
  for (size_t k = 0; alpha < 1.0f; ++k) {
    const float margin = params.march_end ? march_end_margin(t, drift, tan_steps) : 0.0f;
    if (!(t < params.max_distance + float(params.march_end) * margin)) break;
    vec3 pos = origin + cone.direction * t;
    if (k == 0 && start_tie) {
      vec3 shift;
      if (start_face_variant(params.march_end, pos, om, shift)) {
        if (params.march_end < 0) break;
        origin += shift;
        pos = origin + cone.direction * t;
      }
    }
    if (params.march_end < 0 && (margin > 0.0f || start_tie) && near_exit_face(pos, cone.direction, margin, om)) break;
    if (!inside_unit_cube(pos) &&
        !(params.march_end > 0 && just_past_exit_face(pos, cone.direction, margin, om, pos)))
      break;
    const MarchStep g = k < scheduled ? (*schedule)[k] : march_step(t, tan_half, voxel, params);
    const float diameter = g.diameter, lod = g.lod, step = g.step;
    vec4 s = sample(pos, lod, cone.direction);
    // dt0: the side of a voxel of the level sampled (lod as computed, before any clamp).
    if (params.step_correction) s = sh::step_corrected_sample(s, step / (voxel * std::exp2(lod)));
    const float transmit = 1.0f - alpha;
    color += transmit * vec3(s);
    alpha += transmit * s.a;
    if (record) record->push_back({pos, t, diameter, lod, s, vec4(color, alpha)});
    if (params.march_end && diameter > voxel) {  // a step whose length came from tan(aperture / 2)
      drift += march_end_step_drift(cone.aperture, t, step);
      ++tan_steps;
    }
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
