// PCF ties on one shadow map: the visibility values a correct GL may compute at a world point from
// the *same* map (the test's own), where only the float arithmetic of the lookup differs
// (docs/compare.md, "Shading stages on the test's own inputs"). GLSL 4.50 section 4.7.1: + - *
// are correctly rounded, a / b within 2.5 ULP, so the light-space coordinate of a point moves by a
// few ulps of the terms it is summed from; a tap flips only where its window depth lies within
// that of the stored depth + bias, or its texel coordinate within that of a texel edge.
#pragma once

#include "core/math.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// [lo, hi] of one light's PCF visibility at world point p: each tap (stages/shadow_map.h's taps
/// and compare) counted lit in `lo` only where it is lit for every admissible coordinate, in `hi`
/// where it is lit for some. lo <= shadow_visibility(map, p) <= hi. With shadow_compare = linear
/// the filter weights' 8 sub-texel bits add kLinearCompareWeightStep on either side.
struct VisibilityRange {
  float lo = 1.0f, hi = 1.0f;
};
VisibilityRange light_visibility_range(const ShadowMap& map, const Light& light, const vec3& p,
                                       const VctSettings& settings);

/// The same at a surface point p with unit normal n, looked up at its normal-offset point
/// (stages/shadow_map.h, shadow_lookup_point) as the reference computes it, each coordinate of
/// which a correct GL's may miss by lookup_point_margin. A point light whose face ties at p is
/// offset through each face it may select.
VisibilityRange surface_visibility_range(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                                         const VctSettings& settings);

/// How far (per world axis) two correct float evaluations of the normal-offset lookup point
/// p + K w n through matrix m may lie apart (docs/compare.md, "Normal offset"): K's two 3-term dot
/// products within g3 of their terms' magnitudes, |r|^2 within g3, the rest (a division at 2.5
/// ulp, the sums and products) within 12 u; w within g4 of its terms' magnitudes (a w that may be
/// <= 0 on one side is no offset there); the product K w n and the sum with p round once each.
double lookup_point_margin(const mat4& m, const vec3& p, const vec3& n, const VctSettings& settings);

/// The margins, exposed for the tests: how far two correct float evaluations of a light-space
/// coordinate may lie apart. `ndc_error(m, p, row)`: of NDC component `row` (0 x, 1 y, 2 z) of
/// world point p through world -> clip matrix m: each side's clip components within g4 of the
/// sum of their terms' magnitudes S (a 4-term dot product, Higham's g_n = n u / (1 - n u),
/// u = 2^-24; fused or not), the division within 2.5 ulp (GLSL) or 0.5 (C++), so
/// |d ndc| <= 2 g4 (S_row + |ndc| S_w) / |w| + 2 (2.5 + 0.5) u |ndc| (an ulp of x is up to 2u|x|).
/// With `e_world` > 0, p itself is known only within e_world per axis (a normal-offset lookup
/// point): + (sum_j |m_row,j| + |ndc| sum_j |m_w,j|) e_world / |w|, the first-order change.
double ndc_error(const mat4& m, const vec3& p, int row, double e_world = 0.0);

/// Texel-unit margin of a coordinate (ndc * 0.5 + 0.5) * size whose NDC may be off by e_ndc: the
/// add and the multiply round once each on each side (<= u and u * size).
double texel_margin(double e_ndc, int size);

/// Margin of a window depth ndc * 0.5 + 0.5 whose NDC may be off by e_ndc: the add rounds once on
/// each side (<= u, the depth is <= 1).
double depth_margin(double e_ndc);

}  // namespace vct
