// Raster alternatives: the values a correct GL may show at a G-buffer pixel besides the
// reference's own. GL leaves vertex snapping and window coordinates' arithmetic to the
// implementation (GL 4.5 §14.6.1; GL_SUBPIXEL_BITS only says how many bits are kept), so every
// snapped coordinate may be one sub-pixel step (2^-8 pixel) off the reference's. That moves each
// edge by at most what moving the sample by (+-2^-8, +-2^-8) pixel moves it (the edge's normal
// component of either displacement is at most 2^-8 (|n_x| + |n_y|)), the shift the position
// model and the texture slack already use; it can also turn a nearly edge-on triangle's winding
// (raster.h, facing_may_flip), and it moves each triangle's window-depth plane by up to its
// slope times one step, so two surfaces whose depths at the centre lie that close (a smooth
// mesh's front- and back-facing triangles meeting at its silhouette, walls crossing) may be
// ordered either way (depth_tie_margin). Where a shifted sample is covered by another surface (a silhouette
// through the pixel, two walls meeting in a corner, two surfaces crossing) or by none, a correct
// GL may show that surface's values at the centre; where the facing may flip, the negated normal.
// The reference records, per G-buffer stage and channel, the range [lo, hi] of its own value and
// every such alternative (docs/compare.md, "Raster alternatives"); the comparison admits a value
// inside that range plus the pixel's bound, as dEQP's verifiers accept any admissible result.
#pragma once

#include <string>

#include "core/math.h"
#include "freedoms/raster_alternatives.h"
#include "scene/scene.h"
#include "stages/raster.h"
#include "stages/stage_types.h"

namespace vct {

/// The G-buffer stages the range covers, each with its channel count, in GBufferSample order.
struct TieRangeGroup {
  const char* stage;  // stage name without "gbuffer."
  int channels;
};
inline constexpr TieRangeGroup kTieRangeGroups[] = {{"coverage", 1}, {"depth", 1},    {"position", 3},
                                                    {"normal", 3},   {"albedo", 3},   {"material", 4},
                                                    {"specular_color", 3}, {"emission", 3}};

/// Name of channel `c` of `group`'s lower ("lo") or upper ("hi") end in GBuffer::tie_range,
/// e.g. "normal.2.hi" (found by name: EXR files store channels sorted by name).
std::string tie_range_channel_name(const std::string& group, int c, bool upper);

/// Fills g.tie_range from the reference's visibility `vb` (centre sample) and G-buffer `g`:
/// widens the position by the front surface's own plane at the four shifts (a nearly edge-on
/// triangle's position moves along the view ray under a one-step snap), re-rasterizes the scene
/// with the sample at each of the four (+-2^-8, +-2^-8) shifts and widens each pixel's range by
/// the values of any other front surface (or of an empty pixel) found there and of the surface
/// tied in depth with it at that sample, by every surface whose depth at the centre ties with the
/// front one's (each fragment whose depth minus its margin reaches the smallest depth plus margin
/// at the pixel: depth_tied_surfaces), by the negated normal where a front surface's facing may flip,
/// and, where an alpha test may go either way (freedoms/alpha_ties.h), by its other outcome and by
/// the end of the chain of flips (the front-most fragment no GL discards, or the clear values). Each
/// alternative surface comes with its own freedoms: its plane at the shifts and its values +- its
/// own texture slack.
void add_tie_ranges(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb, GBuffer& g);

/// add_tie_ranges in its three parts, for a caller that makes each covered pixel's shifted surface
/// points anyway (add_gbuffer_freedoms, for the texture slack): make_tie_ranges makes g.tie_range;
/// start_tie_range fills pixel (x, row) with the reference's own values, widened by its facing
/// alternative and by its front surface's plane at `positions` (the positions of
/// shifted_surface_points' n points there; n = 0 where the pixel is empty or the centre's ray
/// misses the plane); widen_tie_ranges_by_alternatives then adds every other surface, once
/// start_tie_range has run at every pixel. Per pixel the same steps in the same order: the same
/// bits as add_tie_ranges.
void make_tie_ranges(int width, int height, GBuffer& g);
void start_tie_range(const mat4& view_proj, const VisibilityBuffer& vb, int x, int row, const vec3* positions, int n,
                     GBuffer& g);
void widen_tie_ranges_by_alternatives(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb,
                                      GBuffer& g);

}  // namespace vct
