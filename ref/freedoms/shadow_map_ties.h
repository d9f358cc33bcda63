// Raster alternatives in light space: per shadow-map texel, the range [lo, hi] of every depth a
// correct GL may store there (docs/compare.md, "Raster alternatives", light space). A shadow map
// is an ordinary depth-only render (GL 4.5 section 14.6), so the camera's freedoms apply texel for
// texel (freedoms/raster_alternatives.h), each snapped vertex coordinate one 2^-8 texel step off:
//  - coverage follows the sample shifted by (+-2^-8, +-2^-8) texel: where another triangle is in
//    front there (a silhouette through the texel), or none, its depth at the centre (or the clear
//    value 1) is what GL stores; and a triangle may cover a centre within each edge's own reach
//    (a sliver thinner than two steps, whose edges no common shift crosses at once);
//  - every fragment covering the centre may have its depth plane moved by depth_tie_margin m, and
//    a depth buffer keeps the smallest, so the stored value lies in [min (z - m), min (z + m)]
//    over those fragments: the front surface's own snap and a second fragment within the margins
//    (depth-order ties) at once, without asking which one wins;
//  - where the front-most surface, masks ignored, may pass or fail its alpha test, the other
//    outcome's depth (that surface, or what lies behind it, or the clear value);
//  - a UNORM format stores each end rounded as the map itself is (stored_window_depth).
// The reference's own stored depth always lies inside. Computed from the reference's own scene
// and light matrices only: the test never widens its own allowance.
#pragma once

#include <vector>

#include "core/math.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// The range of one size x size depth map rendered through `view_proj` (GL_LESS, cleared to 1,
/// the scene's alpha masks discard), stored as `format`: an image with channels
/// tie_range_channel_name("depth", 0, lo/hi) ("depth.0.lo", "depth.0.hi"), row 0 = top, as the map.
/// One fused sweep over the triangles finds the shifted samples' and the relaxed world's depths and both margin
/// ends; alpha masks add three visibility passes (freedoms/raster_alternatives.h).
Image shadow_depth_range(const Scene& scene, const mat4& view_proj, int size, ShadowDepthFormat format);

/// Fills every map's tie_range (spot and directional lights) or cube_tie_range (the six faces of a
/// point light) through the matrices render_shadow_maps set.
void add_shadow_tie_ranges(const Scene& scene, const VctSettings& settings, std::vector<ShadowMap>& maps);

}  // namespace vct
