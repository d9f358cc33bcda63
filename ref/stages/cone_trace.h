// One cone marched through the voxel mips (docs/pipeline.md, "Cone marching"). All distances are
// in voxel-texture units: the volume is [0,1]^3 and one base voxel is 1/N.
#pragma once

#include <vector>

#include "core/math.h"
#include "core/settings.h"
#include "stages/stage_types.h"

namespace vct {

struct Cone {
  vec3 origin{0.0f};     // texture space
  vec3 direction{0.0f, 0.0f, 1.0f};  // unit
  float aperture = 0.5f;  // full opening angle, radians
  // Per axis, how far (texture units) a correct test engine's origin may lie from this one: 0
  // where both march from the same floats; set where the re-trace reconstructs the engine's
  // positions (GBuffer::position_margin, compare/partial_gbuffer.h). Read only by the march-end
  // variants (MarchParams::march_end): it widens their faces' margins and, at the first sample,
  // admits a start on the other side of any face (docs/compare.md, "The start-face tie").
  vec3 origin_margin{0.0f};
};

/// How far and how finely to march; from_settings() fills it from VctSettings.
struct MarchParams {
  float start_offset = 0.0f;  // first sample distance (texture units)
  // cone_start = normal: the origin moves this far along the surface normal (texture units) and
  // start_offset is 0; axis: 0. Cones without a surface normal (soft shadows) ignore it.
  float normal_offset = 0.0f;
  float max_distance = 1.7320508f;
  float quality = 0.5f;       // step = diameter * quality
  float min_lod = 0.0f;       // multibounce traces start at level >= 1
  bool step_correction = false;  // sh::step_corrected_sample with dt / dt0 = step / (2^lod / N)
  // The march-end tie (docs/compare.md, "The march-end tie"): 0 the march itself; -1 the faces the
  // cone leaves through and max_distance moved inward, +1 outward, by how far a correct GL's step
  // positions may lie from ours (march_end_margin): the march a GL whose last in-volume sample
  // fell just outside (-1) or just inside (+1, sampled at the face) gives. With a cone's
  // origin_margin the first sample too: -1 a cone whose first sample lies within it of any face
  // is cut (a GL whose origin lay outside breaks at once), +1 one whose first sample lies just
  // outside is marched from the origin moved onto that face (docs/compare.md, "The start-face tie").
  int march_end = 0;
  static MarchParams from_settings(const VctSettings& s, int grid);
  /// The specular cone's: from_settings with the specular_offset_voxels and specular_quality an
  /// engine may give it (settings.h; the source design's: 4 voxels along n, t from 0, step 0.6).
  static MarchParams specular_from_settings(const VctSettings& s, int grid);
  /// The soft-shadow cone's: no surface normal, so it starts along its axis under either cone_start.
  static MarchParams shadow_from_settings(const VctSettings& s, int grid);
  /// Where a cone leaving texture-space point p with unit surface normal n starts.
  vec3 origin_at(const vec3& p, const vec3& n) const { return p + n * normal_offset; }
};

/// One sample of the march, for --explain.
struct ConeSample {
  vec3 position{0.0f};
  float distance = 0.0f;
  float diameter = 0.0f;
  float lod = 0.0f;
  vec4 sampled{0.0f};
  vec4 accumulated{0.0f};  // after this sample
};

/// Front-to-back accumulation: rgb is premultiplied (radiance x opacity), so c += (1-a) s.rgb and
/// a += (1-a) s.a. Returns (accumulated radiance, accumulated opacity). When `record` is given,
/// every sample is appended to it.
vec4 trace_cone(const VoxelMips& mips, const Cone& cone, const MarchParams& params,
                std::vector<ConeSample>* record = nullptr);

/// How far (texture units, along the axis) a correct GL's distance t may lie from ours after the
/// march so far: `drift` = the relative error accumulated by the steps whose length came from
/// tan(aperture / 2) (march_end_step_drift), plus one rounding of t per such step.
float march_end_margin(float t, double drift, int tan_steps);

/// The relative drift one step of length `step` (from t to t + step) adds where its length came
/// from tan(aperture / 2): GLSL 4.50 section 4.7.1 leaves tan to sin / cos (absolute 2^-11 each
/// on [-pi, pi]) and the specular aperture to atan (4096 ulp, tests/gl/shared_header_element_test.cpp),
/// so GL's tan(h) is within eps = 2^-11 (1 / sin h + 1 / cos h) + 2^-11 h / (sin h cos h) + 3 u
/// relative of ours, and t_{k+1} = t_k + step carries eps * step / t_{k+1} more.
double march_end_step_drift(float aperture, float t, float step);

class MipSampler;
class MarchSchedule;
/// The same march on the frame's prepared mips (stages/mip_sampler.h): the same bits, faster.
/// A `schedule` (stages/march_schedule.h) that fits the cone's aperture and params supplies its
/// steps' geometry; any other is ignored.
vec4 trace_cone(const MipSampler& mips, const Cone& cone, const MarchParams& params,
                const MarchSchedule* schedule = nullptr);

}  // namespace vct
