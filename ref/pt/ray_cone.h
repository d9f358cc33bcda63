// The path tracer's texture footprint at the primary hit: a ray cone (Akenine-Möller et al.,
// "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20).
// Primary rays go through pixel centres (pt/camera_ray.h), so without a footprint the primary hit
// point-samples level 0 and aliases exactly as an unmipped rasterizer; with the cone's lambda the
// lookup reads the same mip levels as the VCT G-buffer, and ground truth and VCT see the same
// average albedo at a distance. Secondary vertices keep level 0 (docs/pathtracer.md, "Textures").
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"

namespace vct::pt {

/// The cone's spread angle per pixel: beta = atan(2 tan(yfov / 2) / height) (RTG eq. 20.30).
float pixel_spread_angle(const Camera& camera, int height);

/// Per texture slot of `triangle`'s material: lambda = log2(W / |n . d|) + 0.5 log2(T_a / P_a),
/// W = 2 t tan(beta / 2) the cone's width at distance t, n the triangle's geometric normal, d the
/// unit ray direction, T_a the triangle's area in the slot's level-0 texels (through the
/// KHR_texture_transform scale) and P_a its world area (RTG eqs. 20.4-20.6).
SlotLods ray_cone_lods(const Scene& scene, uint32_t triangle, float t, const vec3& dir,
                       float spread_angle);

}  // namespace vct::pt
