#include "stages/cone_sets.h"

#include <algorithm>
#include <cmath>

#include "shared/vct_shared.h"

namespace vct {

namespace {
float radians(float deg) { return deg * (kPi / 180.0f); }
int grid_of(const VoxelMips& mips) { return mips.iso.empty() ? 1 : std::max(mips.iso[0].nx, 1); }
}  // namespace

DiffuseConeSet trace_diffuse_cones(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s,
                                   const vec3& p, const vec3& n, float rotation, float min_lod,
                                   std::array<std::vector<ConeSample>, kDiffuseCones>* records) {
  MarchParams params = MarchParams::from_settings(s, grid_of(mips));
  params.min_lod = min_lod;
  const sh::Frame frame = sh::frame_from_normal(n);
  const bool cosine = s.diffuse_weighting == DiffuseWeighting::Cosine;
  DiffuseConeSet set;
  for (int i = 0; i < kDiffuseCones; ++i) {
    Cone cone;
    cone.origin = volume.to_texture(p);
    cone.direction = glm::normalize(sh::frame_to_world(frame, sh::diffuse_cone_direction(i, rotation)));
    cone.aperture = radians(s.diffuse_aperture_deg);
    const vec4 c = trace_cone(mips, cone, params, records ? &(*records)[size_t(i)] : nullptr);
    set.cones[size_t(i)] = c;
    set.geometry[size_t(i)] = cone;
    set.radiance += sh::diffuse_cone_weight(i, cosine) * vec3(c);
  }
  return set;
}

float diffuse_rotation_for_pixel(const VctSettings& s, int x, int y) {
  if (!s.random_rotation) return 0.0f;
  return sh::diffuse_cone_rotation(uint32_t(x), uint32_t(y), uint32_t(s.frame));
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
