// Where the alpha test (glTF alphaMode MASK, scene/alpha_mask.h) may go either way between two
// correct rasterizers: the test is a step of the interpolated alpha, and GL leaves the sample's
// alpha free by the bilinear weights' precision and the sample position's snapping
// (docs/compare.md, "Alpha-mask ties"). A flipped sample shows the surface or what lies behind
// it: a geometric-edge tie, admitted by the edge rule only where the edge map flags it.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "freedoms/texture_slack.h"
#include "scene/scene.h"

namespace vct {

/// Bilinear weights with 8 sub-texel bits: each of the two weights off by at most 2^-9, so the
/// filtered alpha moves by at most (2 + 1) * 2^-9 of the four texels' alpha range (<= 1).
constexpr float kAlphaWeightSlack = 3.0f / 512.0f;

/// Every alpha a correct GL may test at one sample: [lo, hi].
struct AlphaRange {
  float lo = 0.0f, hi = 0.0f;
};

/// The base-colour alpha's range over the convex quad of `triangle`'s barycentrics (b1, b2)
/// `corners` (the image of the snap square, in order round it), widened by kAlphaWeightSlack. A
/// lookup takes its extremes anywhere inside the quad, not only at its corners: NEAREST is
/// piecewise constant, so its range is that of every level-0 texel whose cell (grown by the
/// sub-texel precision kSubtexelShift) the quad meets; LINEAR is bilinear between texel centres,
/// so its range is that of the corners of the quad's bounding box cut by those cells
/// (scenes/regressions/seed-2289-small: a noise-masked wall seen edge-on from a point light, whose
/// alpha changes texel at every 2^-8 texel step; docs/compare.md, "Alpha-mask ties"). COLOR_0's
/// alpha is affine in the barycentrics: its extremes are at the corners.
AlphaRange alpha_range_over(const Scene& scene, uint32_t triangle, const glm::dvec2 corners[4]);

/// The range at image pixel (x, row) (row 0 = top) of `triangle` at barycentrics `bary`
/// (b0, b1, b2): alpha_range_over the square of sample points a (+-2^-8, +-2^-8) pixel snap
/// (kVertexSnapStep) may move the sample over. Each vertex snaps on its own, but at a covered
/// centre (barycentrics >= 0) the point interpolated moves by sum l_i d_i, within the same square.
AlphaRange alpha_range(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                       const vec3& bary);

/// The alpha's freedom there: how far alpha_range reaches from the reference's own alpha.
float alpha_freedom(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                    uint32_t triangle, const vec3& bary);

/// True when the triangle is alpha tested and its cutoff lies in alpha_range(): a correct
/// implementation may keep or discard this sample.
bool alpha_test_may_flip(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                         uint32_t triangle, const vec3& bary);

/// As alpha_test_may_flip in a raster whose barycentrics are affine in window coordinates (the
/// voxelizer's orthographic projection): `db_dx`, `db_dy` are (b1, b2) per pixel, so a sample moved
/// by (+-r, +-r) pixels moves the barycentrics over the parallelogram r (+-db_dx +- db_dy); r =
/// `reach`, the snap's reach at the fragment (2^-8 inside the triangle, more where it is
/// extrapolated: freedoms/fragment_slack.h voxel_snap_reach).
bool alpha_test_may_flip_affine(const Scene& scene, uint32_t triangle, const vec3& bary, double reach,
                                const glm::dvec2& db_dx, const glm::dvec2& db_dy);

}  // namespace vct
