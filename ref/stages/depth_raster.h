// Depth-only rasterization: what the shadow maps need. Same GL rules and the same bits as the
// visibility buffer's depth (stages/raster.h), without triangle ids or barycentrics per pixel.
#pragma once

#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// Window depth at each pixel centre of a width x height view (GL_LESS, cleared to 1, no culling),
/// row 0 = top: byte for byte render_visibility(positions, triangles, view_proj, width,
/// height).depth. Same set-up, coverage test (solved per row: centre_row_span) and depth formula
/// (interpolate_window_depth); parallel over the same bands of rows, deterministic.
/// With `alpha_scene` (whose triangles these are), fragments of alpha-tested triangles that
/// surface_masked() cuts away write nothing (scene/alpha_mask.h), as a discard in GL's depth pass.
std::vector<float> render_depth(const std::vector<vec3>& positions,
                                const std::vector<uvec3>& triangles, const mat4& view_proj,
                                int width, int height, const Scene* alpha_scene = nullptr);

}  // namespace vct
