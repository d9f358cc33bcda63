// The cones the final frame traces at one surface point: the seed's 5 diffuse cones, the specular
// cone along the reflected view vector and the soft-shadow cone toward a light
// (docs/pipeline.md, "Diffuse cones", "Specular cone", "Soft shadows"). Inputs in world space;
// the volume mapping (uniform scale) turns them into texture space without changing directions.
#pragma once

#include <array>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/cone_trace.h"

namespace vct {

constexpr int kDiffuseCones = 5;

/// Per-cone results of one diffuse cone set, kept for dumps and --explain.
struct DiffuseConeSet {
  vec3 radiance{0.0f};                      // weighted combination (what the frame uses)
  std::array<vec4, kDiffuseCones> cones{};  // each cone's accumulated (rgb, opacity)
  std::array<Cone, kDiffuseCones> geometry{};
};

/// Traces the diffuse cone set at world point p with unit normal n, rotated by `rotation` radians
/// about n. `min_lod` > 0 for multibounce (previous frame's mips at level >= 1).
/// `records`, if given, receives every cone's samples.
DiffuseConeSet trace_diffuse_cones(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s,
                                   const vec3& p, const vec3& n, float rotation, float min_lod = 0.0f,
                                   std::array<std::vector<ConeSample>, kDiffuseCones>* records = nullptr);

/// The cone rotation of pixel (x, y) (row 0 = top) for this frame, or 0 when rotation is off.
float diffuse_rotation_for_pixel(const VctSettings& s, int x, int y);

/// Specular cone at p: along reflect(-v, n), aperture sh::specular_cone_aperture(roughness).
Cone specular_cone(const VoxelVolume& volume, const vec3& p, const vec3& n, const vec3& v, float roughness);
vec4 trace_specular_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                         const vec3& n, const vec3& v, float roughness, std::vector<ConeSample>* record = nullptr);

/// Soft-shadow visibility 1 - opacity of a cone from p toward light_position (world), aperture
/// settings.soft_shadow_aperture_deg, marched no further than the light.
float trace_shadow_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                        const vec3& light_position, std::vector<ConeSample>* record = nullptr);

}  // namespace vct
