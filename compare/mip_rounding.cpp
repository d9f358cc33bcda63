#include "compare/mip_rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stages/reduction.h"

namespace vct::cmp {
namespace {

const double kUnitRoundoff = std::ldexp(1.0, -24);  // float's unit roundoff u

// An interval of what the float arithmetic of a mip shader can leave before its explicit rounding.
struct Interval {
  float lo, hi;
};
// The exact value x widened by err, then one float step outward, so that converting the ends to
// float cannot narrow the interval.
Interval widened(double x, double err) {
  const float inf = std::numeric_limits<float>::infinity();
  return {std::nextafter(float(x - err), -inf), std::nextafter(float(x + err), inf)};
}

// mip_iso.comp: the exact mean x of the eight children, widened by the rounding of the seven float
// additions (any order, FMA or not: each adds at most u of its result, and every partial sum is at
// most S = sum |child|) and, for RGBA8, of the product by 255 (u |x|).
Interval iso_interval(const float* const kids[8]) {
  double x = 0.0, s = 0.0;
  for (int i = 0; i < 8; ++i) x += double(*kids[i]), s += std::abs(double(*kids[i]));
  x *= 0.125;
  return widened(x, kUnitRoundoff * (7.0 * s * 0.125 + std::abs(x)));
}

// mip_aniso.comp: per pair, comp = near + (1 - near.a) * far (alpha likewise), then the mean of the
// four pairs. GLSL 4.50 §4.7.1 lets a compiler fuse or distribute without `precise`, so a pair is
// either n + (1 - a)f (three roundings: 1 - a, the product, the sum) or n + f - a f (three: the
// product and two sums); each adds at most u of a result bounded by |n| + (1 + |a|)|f|, so a pair
// errs by at most 3u (|n| + (1 + |a|)|f|). The three sums of the four pairs add at most u of a
// partial sum each, ≤ 3u of the same total; ×0.25 is exact. With A = 0.25 Σ (|n| + (1 + |a|)|f|)
// the error is ≤ 6u A (1 + 3u) ≤ 7u A (the 7 holds the u² terms), plus u |x| for RGBA8's ×255.
Interval aniso_interval(const float* const near[4], const float* const far[4], const float near_alpha[4]) {
  double x = 0.0, a = 0.0;
  for (int p = 0; p < 4; ++p) {
    const double n = *near[p], f = *far[p], na = near_alpha[p];
    x += n + (1.0 - na) * f;
    a += std::abs(n) + (1.0 + std::abs(na)) * std::abs(f);
  }
  x *= 0.25, a *= 0.25;
  return widened(x, kUnitRoundoff * (7.0 * a + std::abs(x)));
}

// The admissible stored values between the ends' roundings (every step is monotone: the roundings,
// and the aniso shader's min(alpha, 1)); counts what lies outside.
void judge_value(MipRoundingCheck& r, Interval iv, float stored, bool half, bool clamp_to_one, int x, int y, int z) {
  if (clamp_to_one) iv = {std::min(iv.lo, 1.0f), std::min(iv.hi, 1.0f)};
  const auto quantize = [&](float v) { return half ? quantize_half(v) : quantize_unorm8(v); };
  ++r.checked;
  if (stored >= quantize(iv.lo) && stored <= quantize(iv.hi)) return;
  if (r.violations++ == 0) r.worst_x = x, r.worst_y = y, r.worst_z = z;
}

bool all_finite(const float* const* values, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(*values[i])) return false;
  return true;
}

bool checkable(const Volume& child, const Volume& parent, const std::string& storage) {
  return (storage == "rgba16f" || storage == "rgba8") && child.nx == 2 * parent.nx && child.ny == 2 * parent.ny &&
         child.nz == 2 * parent.nz;
}

int channels_of(const Volume& child, const Volume& parent) {
  return std::min(std::min(child.channels, parent.channels), 4);
}

}  // namespace

MipRoundingCheck check_iso_mip_rounding(const Volume& child, const Volume& parent, const std::string& storage) {
  MipRoundingCheck r;
  if (!checkable(child, parent, storage)) return r;
  const int ch = channels_of(child, parent);
  for (int z = 0; z < parent.nz; ++z)
    for (int y = 0; y < parent.ny; ++y)
      for (int x = 0; x < parent.nx; ++x)
        for (int c = 0; c < ch; ++c) {
          const float* kids[8];
          for (int k = 0; k < 8; ++k) kids[k] = child.voxel(2 * x + (k & 1), 2 * y + (k >> 1 & 1), 2 * z + (k >> 2)) + c;
          const float stored = parent.voxel(x, y, z)[c];
          if (!all_finite(kids, 8) || !std::isfinite(stored)) continue;
          judge_value(r, iso_interval(kids), stored, storage == "rgba16f", false, x, y, z);
        }
  return r;
}

MipRoundingCheck check_aniso_mip_rounding(const Volume& child, const Volume& parent, const std::string& storage,
                                          int direction) {
  MipRoundingCheck r;
  if (!checkable(child, parent, storage) || direction < 0 || direction > 5 || channels_of(child, parent) < 4) return r;
  const int axis = direction / 2, a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const bool positive = direction % 2 == 0;  // marching toward +axis: the lower index is met first
  for (int z = 0; z < parent.nz; ++z)
    for (int y = 0; y < parent.ny; ++y)
      for (int x = 0; x < parent.nx; ++x) {
        const float* near[4];
        const float* far[4];
        for (int p = 0; p < 4; ++p) {
          int lo[3] = {2 * x, 2 * y, 2 * z};
          lo[a1] += p & 1;
          lo[a2] += p >> 1;
          int hi[3] = {lo[0], lo[1], lo[2]};
          ++hi[axis];
          near[p] = child.voxel(positive ? lo[0] : hi[0], positive ? lo[1] : hi[1], positive ? lo[2] : hi[2]);
          far[p] = child.voxel(positive ? hi[0] : lo[0], positive ? hi[1] : lo[1], positive ? hi[2] : lo[2]);
        }
        float near_alpha[4];
        for (int p = 0; p < 4; ++p) near_alpha[p] = near[p][3];
        for (int c = 0; c < 4; ++c) {
          const float* n[4] = {near[0] + c, near[1] + c, near[2] + c, near[3] + c};
          const float* f[4] = {far[0] + c, far[1] + c, far[2] + c, far[3] + c};
          const float stored = parent.voxel(x, y, z)[c];
          if (!all_finite(n, 4) || !all_finite(f, 4) || !std::isfinite(stored)) continue;
          const float* alphas[4] = {&near_alpha[0], &near_alpha[1], &near_alpha[2], &near_alpha[3]};
          if (!all_finite(alphas, 4)) continue;
          judge_value(r, aniso_interval(n, f, near_alpha), stored, storage == "rgba16f", c == 3, x, y, z);
        }
      }
  return r;
}

}  // namespace vct::cmp
