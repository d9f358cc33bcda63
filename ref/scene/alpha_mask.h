// The alpha test of glTF alphaMode MASK (and BLEND, rendered as MASK at 1/2) on the CPU: one
// definition that the shadow-map and G-buffer rasterizers, both voxelizers and the path tracer's
// Embree filter call, so every CPU pass discards the same surface points. The comparison itself
// is vct_shared.h's alpha_discards, shared with gl/shaders/alpha_mask.glsl (docs/scenes.md,
// "Alpha modes").
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace vct {

/// Whether triangle's material has an alpha test at all (Mask or Blend). Triangles for which this
/// is false never call base_color_alpha, so opaque scenes pay nothing.
bool triangle_alpha_tested(const Scene& scene, uint32_t triangle);

/// glTF 2.0 §3.9.4's alpha at barycentrics (1-b1-b2, b1, b2): base_color_factor.a times the base
/// colour texture's alpha, sampled as evaluate_material samples it (scene/surface.h:
/// sample_texture at level 0; alpha is linear in SRGB8_ALPHA8 too) x COLOR_0's alpha when the
/// scene has vertex colours.
float base_color_alpha(const Scene& scene, uint32_t triangle, float b1, float b2);

/// True when the point is cut away: an alpha-tested material whose alpha is below its cutoff.
bool surface_masked(const Scene& scene, uint32_t triangle, float b1, float b2);

/// True if any triangle of the scene is alpha tested.
bool scene_has_alpha_test(const Scene& scene);

}  // namespace vct
