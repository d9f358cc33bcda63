// Level of detail as GL 4.5 §8.14 defines it: the scale factor rho from the derivatives of the
// texel coordinates (u, v) = (s * w_base, t * h_base), lambda = log2(rho), and the levels and
// weights each minification filter takes (§8.14.2 nearest/linear in a level, §8.14.3 mipmapping).
// The CPU computes derivatives analytically (stages/uv_derivatives.h for the camera, inject.cpp
// for the voxel grid); GL's freedom (quad differences, the approximated rho, LOD precision) is the
// admissible interval [lo, hi] of LodRange (docs/compare.md, "Texture LOD").
#pragma once

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// Derivatives of a surface point's two UV sets along the two raster axes (window x and y, or
/// the voxel projection's two in-plane axes), in UV units per pixel.
struct UvDerivatives {
  vec2 dx[2]{vec2(0.0f), vec2(0.0f)};
  vec2 dy[2]{vec2(0.0f), vec2(0.0f)};
};

/// Texel-space derivatives of one texture slot: the UV derivatives through the slot's
/// KHR_texture_transform (its linear part R S) and scaled by level 0's size.
struct TexelDerivatives {
  glm::dvec2 dx{0.0}, dy{0.0};
};
TexelDerivatives texel_derivatives(const Texture& texture, const TextureRef& ref,
                                   const UvDerivatives& d);

/// lambda_base = log2(rho) with GL's exact rho = max(|d/dx|, |d/dy|) (§8.14.1 eq. 8.8); -inf
/// for zero derivatives (magnified).
double exact_lod(const TexelDerivatives& d);

/// The admissible lambdas GL may use for one texture read (docs/compare.md, "Texture LOD").
struct LodRange {
  double lo = 0.0, hi = 0.0;
};

/// LOD precision GL leaves open (GL 4.5 §8.14.1 gives lambda = log2(rho) and no precision):
/// lambda may be off by 2^-4. dEQP's texture filtering tests verify with LodPrecision::lodBits 6
/// first and, where that fails, accept lodBits 4 as a QualityWarning (a conformant result, not a
/// failure); llvmpipe needs it: lambda = 0.5 * fast_log2(rho^2), log2 with a linear mantissa
/// (exact at powers of two), up to 0.0431 below log2(rho) (docs/compare.md, "Texture LOD").
constexpr double kLodPrecision = 1.0 / 16.0;

/// Widens a range by the approximations §8.14.1 allows for rho, for one candidate derivative
/// pair: max(|du|, |dv|) <= f <= |du| + |dv| per axis, rho = max(f_x, f_y).
struct RhoBounds {
  double x_lo = 1e300, x_hi = 0.0, y_lo = 1e300, y_hi = 0.0;
  void add_x(const glm::dvec2& d);
  void add_y(const glm::dvec2& d);
  /// [log2(max(x_lo, y_lo)) - kLodPrecision, log2(max(x_hi, y_hi)) + kLodPrecision].
  LodRange range() const;
};

/// Which levels a lookup at `lambda` reads and how it blends them (§8.14, §8.14.3): magnified
/// (lambda <= 0) -> the mag filter on level 0; NEAREST/LINEAR -> level 0; *_MIPMAP_NEAREST ->
/// d = 0 if lambda <= 1/2, else ceil(lambda + 1/2) - 1, clamped to q; *_MIPMAP_LINEAR ->
/// d1 = floor(lambda), d2 = d1 + 1, weight frac(lambda) on d2, both clamped to q (d1 = d2 = q
/// once lambda >= q). `q` = the last level (available levels - 1).
struct LevelBlend {
  int level1 = 0, level2 = 0;
  float weight2 = 0.0f;  // (1 - weight2) * level1 + weight2 * level2
  bool linear = true;    // filter within a level: LINEAR (true) or NEAREST
};
LevelBlend select_levels(const Texture& texture, double lambda, int q);

}  // namespace vct
