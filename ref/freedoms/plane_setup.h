// The window depth a GL computes from a plane equation set up in single precision.
//
// GL 4.5 §14.6.1 (eq. 14.10) defines a fragment's depth by its barycentrics in window space and
// leaves the arithmetic to the implementation (§2.3.4.1). The reference evaluates exact integer
// edge functions and rounds three times (depth_tie_margin's 2^-22); a rasterizer may instead set up
// the plane z = z_k + dz/dx (x - x_k) + dz/dy (y - y_k) once per triangle in float from its window
// vertices (Mesa llvmpipe's set-up does, from the vertex it takes first; clipping re-orders the
// vertices). The gradient's float set-up is ill-conditioned on a sliver: its area and numerators
// are differences of products much larger than themselves, so one rounding of each product moves
// the gradient by (S / |A|) u, S the products' sum of magnitudes, and the error grows with the
// distance from the first vertex (docs/compare.md, "Light space: shadow maps", plane set-up;
// scenes/regressions/seed-2463-small: a 0.017-texel-wide sliver of a triangle clipped by a spot's
// near plane, llvmpipe 1.26e-4 above the plane where its depth margin was 3.0e-5).
#pragma once

#include "stages/raster.h"

namespace vct {

/// Unit roundoff of IEEE single precision.
constexpr double kFloatRoundoff = 1.0 / 16777216.0;  // 2^-24

/// How far a depth evaluated anywhere in the triangle's pixel box from a plane equation set up in
/// single precision may lie from the exact plane, whichever vertex the set-up starts from: with
/// edge vectors (dx_j, dy_j, dz_j) from that vertex, area A = dx1 dy2 - dx2 dy1 and numerators
/// N_x = dz1 dy2 - dz2 dy1, N_y = dx1 dz2 - dx2 dz1, each difference of two rounded products of
/// rounded differences lies within 4u of the sum of its products' magnitudes (S_A, S_x, S_y); so
/// dz/dx = N_x / A within (4u S_x + |dz/dx| 4u S_A) / |A| + u |dz/dx|, likewise dz/dy, and the
/// evaluation at a centre (cx, cy) adds those times |cx - x_k|, |cy - y_k| (at most the box's
/// extent) and three roundings of its terms, whether it runs from vertex k or from the window
/// origin through a0 = z_k - dz/dx x_k - dz/dy y_k. In window depth units; pixels for x, y.
double plane_setup_margin(const RasterTriangle& t);

}  // namespace vct
