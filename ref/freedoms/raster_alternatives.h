// What one sub-pixel step of vertex snapping leaves free in a rasterization, shared by the camera's
// raster alternatives (freedoms/gbuffer_ties.h) and the shadow maps' (freedoms/shadow_map_ties.h). GL
// leaves how window coordinates are computed and rounded to the sub-pixel grid to the
// implementation (GL 4.5 section 14.6.1; GL_SUBPIXEL_BITS only says how many bits are kept), so
// every snapped coordinate may be one step (2^-8 pixel) off the reference's: edges move like the
// sample moved by (+-2^-8, +-2^-8), depth planes by their slope times one step, and an alpha test
// near its cutoff may go either way (docs/compare.md, "Raster alternatives").
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"
#include "stages/raster.h"

namespace vct {

/// The four sample shifts (pixels, window axes) whose coverage the alternatives follow.

/// Sample offset k (0..3) of the four (+-2^-8, +-2^-8) shifts from the pixel centre, in
/// sub-pixel steps from the pixel's lower-left corner (x, y): (127 or 129, 127 or 129).
inline void shifted_sample_steps(int k, int64_t& sx, int64_t& sy) {
  sx = kSubpixelScale / 2 + ((k & 1) ? 1 : -1);
  sy = kSubpixelScale / 2 + ((k & 2) ? 1 : -1);
}

/// How far a correct GL's window depth of triangle `t` at a pixel centre may lie from the
/// reference's: its plane moved by one sub-pixel step on each axis, 2^-8 (|dz/dx| + |dz/dy|) per
/// pixel (the d32f-depth model's slope term; dz/dx = sum a_i z_i / area2 per step), plus 2^-22
/// for the float evaluation b0 z0 + b1 z1 + b2 z2 and its storage as D32F (three roundings of
/// values below 1, each at most half an ulp of 1, 2^-24, with room to spare) -- or, where larger,
/// what a plane equation set up and evaluated in single precision may be off by
/// (plane_setup_margin: a few roundings on ordinary triangles, large on slivers only). The slope
/// term carries depth_plane_extrapolation_factor; where that is infinite the margin is 1 (any
/// depth).
double depth_tie_margin(const RasterTriangle& t);

/// The factor on depth_tie_margin's slope term: how far a plane through vertices one step off may
/// be extrapolated at a centre some snap covers, 1 + 4 sum r_i / (A - R) (the derivation is at the
/// definition); infinity where a snap may close the triangle (A <= R: its plane is any plane).
double depth_plane_extrapolation_factor(const RasterTriangle& t);

/// Per pixel, the surface behind `front`'s: the fragment of another source triangle with the
/// smallest depth (triangle -1: none). Alpha-masked fragments are discarded. Rasterized as
/// render_visibility does (bands, triangles in index order), so the result does not depend on the
/// thread count.
VisibilityBuffer other_surfaces(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& front);

/// Depth order (docs/compare.md, "Raster alternatives", "Depth order" and "Every surface tied in
/// depth"): every surface other than `front`'s that a correct GL may keep under GL_LESS at each
/// pixel. Each fragment's depth may lie anywhere in [z - m, z + m] (m = depth_tie_margin, its plane
/// moved by one snap step and the float evaluation), each on its own, so fragment S may come out in
/// front iff z_S - m_S <= min over the other fragments T of z_T + m_T; since z_S - m_S <= z_S + m_S,
/// that is z_S - m_S <= the minimum of z + m over all fragments at the pixel, the front's included.
/// Every such fragment is admissible, not only the one with the smallest z - m: a plane, its
/// coplanar twin and a third surface crossing them at one centre tie all three ways (hunt seed
/// 2717). Returned as layers: layer k holds each pixel's k-th tied fragment (in triangle order),
/// and `front`'s own entry where a pixel has fewer (callers skip what equals their front). Coverage
/// is taken at `sample` (pixel units from the pixel's corner; `front` rendered with the same
/// sample), depths and barycentrics at the centre, as render_visibility. Alpha-tested fragments
/// count by what every correct GL does with them (alpha_ties.h): one whose test may flip is a
/// candidate and does not bound the others; one cut for certain is neither.
/// With `candidates` = Possible the candidates are every fragment some snap of its vertices makes
/// cover the sample (the ceiling still from the reference's coverage): a sliver thinner than a
/// snap step beside the front's edge may cover a centre no common shift of the sample puts inside
/// it (hunt seed 6 of the large class, docs/compare.md "Raster alternatives", "A sliver's own snap").
std::vector<VisibilityBuffer> depth_tied_surfaces(const Scene& scene, const mat4& view_proj,
                                                  const VisibilityBuffer& front, vec2 sample = vec2(0.5f),
                                                  SnapWorld candidates = SnapWorld::Reference);

/// render_visibility(scene.positions, scene.triangles, view_proj, w, h, &scene, sample), returned,
/// and depth_tied_surfaces of it at `sample`, into `tied`: the front surfaces and the depth ties'
/// ceiling from one pass over the fragments (the same fragments in the same order as each makes
/// alone), the same bits as the two calls.
VisibilityBuffer visibility_and_depth_ties(const Scene& scene, const mat4& view_proj, int w, int h, vec2 sample,
                                           std::vector<VisibilityBuffer>& tied);

/// Alpha-mask ties (freedoms/alpha_ties.h): where the front-most surface a correct GL may keep (masks
/// applied only where they cannot flip: surfaces cut away for certain in front of it are skipped)
/// may pass or fail its alpha test (`may_flip` 1), `surface` holds the other outcome: that surface
/// where the reference (`vb`, rendered with the masks) discarded it, what lies behind it
/// (other_surfaces; triangle -1 = nothing, the clear value) where the reference kept it.
/// The front-most fragment at each pixel centre that no correct GL discards: an untested triangle,
/// or an alpha-tested one that passes where its test cannot flip. Every fragment in front of it is
/// cut away for certain or may flip, so a correct GL may store any of them or this one, and nothing
/// behind it (triangle -1: every fragment may be cut away, so the clear value too). The deepest
/// outcome of a chain of alpha flips (docs/compare.md, "Alpha-mask ties").
VisibilityBuffer front_certainly_kept(const Scene& scene, const mat4& view_proj, int w, int h);

/// Every fragment in front of `kept` (front_certainly_kept's) that may flip (the middle of a chain of alpha
/// flips): a correct GL may cut away every fragment in front of it (each is cut for certain or may
/// flip) and keep it, so each is admissible, not only the chain's two ends (docs/compare.md,
/// "Alpha-mask ties", "Every layer of a chain"). Returned as layers, as depth_tied_surfaces: layer k
/// holds each pixel's k-th such fragment (in triangle order), and `front`'s own entry where a pixel
/// has fewer or where it is `front`'s own triangle; empty when no pixel has one.
std::vector<VisibilityBuffer> alpha_chain_surfaces(const Scene& scene, const mat4& view_proj,
                                                   const VisibilityBuffer& front, const VisibilityBuffer& kept);

struct AlphaFlipSurfaces {
  VisibilityBuffer surface;
  std::vector<uint8_t> may_flip;
};
AlphaFlipSurfaces alpha_flip_surfaces(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb);

}  // namespace vct
