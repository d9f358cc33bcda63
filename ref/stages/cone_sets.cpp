#include "stages/cone_sets.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/error.h"

namespace vct {

static_assert(kMaxDiffuseCones == kMaxDiffuseConeCount, "the shared header and the settings disagree on the cone limit");

namespace {
float radians(float deg) { return deg * (kPi / 180.0f); }
int grid_of(const VoxelMips& mips) { return mips.iso.empty() ? 1 : std::max(mips.iso[0].nx, 1); }
}  // namespace

sh::DiffuseConeBlock diffuse_cone_block(const VctSettings& s) {
  const int count = s.diffuse_cone_count;
  if (count < 1 || count > kMaxDiffuseCones)
    throw InputError("", "diffuse_cone_count must be in 1.." + std::to_string(kMaxDiffuseCones) + " (got " +
                             std::to_string(count) + ")");
  if (!(s.diffuse_cone_tilt_deg > 0.0f && s.diffuse_cone_tilt_deg < 90.0f)) {
    std::ostringstream got;
    got << s.diffuse_cone_tilt_deg;
    throw InputError("", "diffuse_cone_tilt_deg must be in (0, 90) (got " + got.str() + ")");
  }
  // In double, rounded once: for 45 degrees both give 0.70710677f, the seed's literal
  // 0.70710678118654752f (tests/ref/cone_set_test.cpp checks), and for count 5 the step
  // 2 pi / 4 rounds to exactly 0.5f * SH_PI.
  const double tilt = double(s.diffuse_cone_tilt_deg) * (3.14159265358979323846 / 180.0);
  const float sin_t = float(std::sin(tilt)), cos_t = float(std::cos(tilt));
  const float step = count > 1 ? float(2.0 * 3.14159265358979323846 / double(count - 1)) : 0.0f;
  sh::DiffuseConeBlock b;
  b.shape = vec4(sin_t, cos_t, step, float(count));
  if (s.diffuse_weighting == DiffuseWeighting::Cosine) {
    // The seed's order of operations (1 + 4 c, then each cosine over the total), so count 5 keeps
    // its bits.
    const float total = 1.0f + float(count - 1) * cos_t;
    b.weights = vec4(1.0f / total, cos_t / total, 0.0f, 0.0f);
  } else {
    b.weights = vec4(1.0f, 1.0f, 0.0f, 0.0f);
  }
  return b;
}

DiffuseConeSet trace_diffuse_cones(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s,
                                   const vec3& p, const vec3& n, float rotation, float min_lod,
                                   std::vector<std::vector<ConeSample>>* records) {
  MarchParams params = MarchParams::from_settings(s, grid_of(mips));
  params.min_lod = min_lod;
  const sh::Frame frame = sh::frame_from_normal(n);
  const sh::DiffuseConeBlock block = diffuse_cone_block(s);
  DiffuseConeSet set;
  set.count = sh::diffuse_cone_count(block);
  if (records) records->assign(size_t(set.count), {});
  for (int i = 0; i < set.count; ++i) {
    Cone cone;
    cone.origin = volume.to_texture(p);
    cone.direction = glm::normalize(sh::frame_to_world(frame, sh::diffuse_cone_direction(i, rotation, block)));
    cone.aperture = radians(s.diffuse_aperture_deg);
    const vec4 c = trace_cone(mips, cone, params, records ? &(*records)[size_t(i)] : nullptr);
    set.cones[size_t(i)] = c;
    set.geometry[size_t(i)] = cone;
    set.weights[size_t(i)] = sh::diffuse_cone_weight(i, block);
    set.radiance += set.weights[size_t(i)] * vec3(c);
  }
  return set;
}

float diffuse_rotation_for_pixel(const VctSettings& s, int x, int y) {
  if (!s.random_rotation) return 0.0f;
  return sh::diffuse_cone_rotation(uint32_t(x), uint32_t(y), uint32_t(s.frame), diffuse_cone_block(s));
}

Cone specular_cone(const VoxelVolume& volume, const vec3& p, const vec3& n, const vec3& v, float roughness) {
  Cone cone;
  cone.origin = volume.to_texture(p);
  cone.direction = glm::normalize(glm::reflect(-v, n));
  // Same clamp as sh::surface_pbr, so the cone matches the roughness the BRDF uses.
  cone.aperture = sh::specular_cone_aperture(std::max(roughness, sh::MIN_ROUGHNESS));
  return cone;
}

vec4 trace_specular_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                         const vec3& n, const vec3& v, float roughness, std::vector<ConeSample>* record) {
  return trace_cone(mips, specular_cone(volume, p, n, v, roughness), MarchParams::from_settings(s, grid_of(mips)),
                    record);
}

float trace_shadow_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                        const vec3& light_position, std::vector<ConeSample>* record) {
  Cone cone;
  cone.origin = volume.to_texture(p);
  const vec3 to_light = volume.to_texture(light_position) - cone.origin;
  const float dist = glm::length(to_light);
  if (dist <= 0.0f) return 1.0f;
  cone.direction = to_light / dist;
  cone.aperture = radians(s.soft_shadow_aperture_deg);
  MarchParams params = MarchParams::from_settings(s, grid_of(mips));
  params.max_distance = std::min(params.max_distance, dist);  // occluders behind the light don't count
  return 1.0f - trace_cone(mips, cone, params, record).a;
}

}  // namespace vct
