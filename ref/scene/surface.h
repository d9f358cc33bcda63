// A point on a triangle and its textured material: the one definition the G-buffer, voxel light
// injection and the path tracer all use, so they agree on what a surface is.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// Interpolated vertex attributes at barycentrics (1-b1-b2, b1, b2) of a triangle.
struct SurfacePoint {
  uint32_t triangle = 0;
  vec3 position{0.0f};
  vec3 geometric_normal{0.0f, 0.0f, 1.0f};  // from the winding (v1-v0)x(v2-v0), unit
  vec3 normal{0.0f, 0.0f, 1.0f};            // interpolated vertex normal, unit
  vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};     // interpolated tangent, w = handedness
  vec2 uv0{0.0f}, uv1{0.0f};
};

/// Material values at a surface point after texturing and normal mapping.
struct SurfaceMaterial {
  vec3 albedo{1.0f};
  float opacity = 1.0f;  // base colour alpha (informational; all surfaces are opaque here)
  float metallic = 0.0f;
  float roughness = 1.0f;
  float specular_factor = 1.0f;
  vec3 specular_color{1.0f};
  vec3 emission{0.0f};
  vec3 shading_normal{0.0f, 0.0f, 1.0f};  // unit, after the normal map
};

SurfacePoint interpolate_surface(const Scene& scene, uint32_t triangle, float b1, float b2);

/// Evaluates the triangle's material at `p`. Textures are sampled bilinearly at mip level 0 with
/// GL's texel-centre convention and the texture's wrap modes; sRGB textures (base colour,
/// emissive) are decoded per texel before filtering, as GL does for SRGB8_ALPHA8.
SurfaceMaterial evaluate_material(const Scene& scene, const SurfacePoint& p);

/// Bilinear sample of an RGBA8 texture in [0,1] units (decoded from sRGB when `srgb`).
vec4 sample_texture(const Texture& tex, vec2 uv, bool srgb);

/// Applies a tangent-space normal map value (already in [-1,1]^3, z reconstructed if needed).
vec3 apply_normal_map(const vec3& normal, const vec4& tangent, vec3 tangent_space_normal, float scale);

}  // namespace vct
