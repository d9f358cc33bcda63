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

/// The alpha's freedom at image pixel (x, row) (row 0 = top) of `triangle` at barycentrics `bary`
/// (b0, b1, b2): kAlphaWeightSlack plus the largest change of the reference's own alpha when the
/// sample moves by (+-2^-8, +-2^-8) pixels (kVertexSnapStep, vertex snapping).
float alpha_freedom(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                    uint32_t triangle, const vec3& bary);

/// True when the triangle is alpha tested and |alpha - cutoff| <= alpha_freedom(): a correct
/// implementation may keep or discard this sample.
bool alpha_test_may_flip(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                         uint32_t triangle, const vec3& bary);

/// As alpha_test_may_flip in a raster whose barycentrics are affine in window coordinates (the
/// voxelizer's orthographic projection): `db_dx`, `db_dy` are (b1, b2) per pixel, so a sample moved
/// by (+-r, +-r) pixels moves the barycentrics by r (+-db_dx +- db_dy); r = `reach`, the snap's
/// reach at the fragment (2^-8 inside the triangle, more where it is extrapolated:
/// freedoms/fragment_slack.h voxel_snap_reach).
bool alpha_test_may_flip_affine(const Scene& scene, uint32_t triangle, const vec3& bary, double reach,
                                const glm::dvec2& db_dx,
                                const glm::dvec2& db_dy);

}  // namespace vct
