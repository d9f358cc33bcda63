#include "compare/mip_rounding.h"

#include <cmath>
#include <limits>

#include "stages/reduction.h"

namespace vct::cmp {
namespace {

// The interval the float arithmetic of mip_iso.comp can leave before its explicit rounding: the
// exact mean x of the eight children, widened by the rounding of the seven float additions (any
// order, FMA or not: each adds at most 2^-24 of its result, and every partial sum is at most
// S = sum |child|) and, for RGBA8, of the product by 255 (2^-24 |x|). The bounds are then moved
// one float step outward, so that converting them to float cannot narrow the interval.
struct Interval {
  float lo, hi;
};
Interval sum_interval(const float* c[8]) {
  double x = 0.0, s = 0.0;
  for (int i = 0; i < 8; ++i) x += double(*c[i]), s += std::abs(double(*c[i]));
  x *= 0.125;
  const double eps = std::ldexp(1.0, -24) * (7.0 * s * 0.125 + std::abs(x));
  const float inf = std::numeric_limits<float>::infinity();
  return {std::nextafter(float(x - eps), -inf), std::nextafter(float(x + eps), inf)};
}

}  // namespace

MipRoundingCheck check_iso_mip_rounding(const Volume& child, const Volume& parent, const std::string& storage) {
  MipRoundingCheck r;
  const bool half = storage == "rgba16f";
  if (!half && storage != "rgba8") return r;
  if (child.nx != 2 * parent.nx || child.ny != 2 * parent.ny || child.nz != 2 * parent.nz) return r;
  const int ch = std::min(std::min(child.channels, parent.channels), 4);
  const auto quantize = [&](float v) { return half ? quantize_half(v) : quantize_unorm8(v); };
  for (int z = 0; z < parent.nz; ++z)
    for (int y = 0; y < parent.ny; ++y)
      for (int x = 0; x < parent.nx; ++x)
        for (int c = 0; c < ch; ++c) {
          const float* kids[8];
          for (int k = 0; k < 8; ++k) kids[k] = child.voxel(2 * x + (k & 1), 2 * y + (k >> 1 & 1), 2 * z + (k >> 2)) + c;
          bool finite = true;
          for (const float* k : kids) finite = finite && std::isfinite(*k);
          const float stored = parent.voxel(x, y, z)[c];
          if (!finite || !std::isfinite(stored)) continue;
          const Interval iv = sum_interval(kids);
          ++r.checked;
          // Both roundings are monotone: the admissible values are those between the ends' roundings.
          if (stored >= quantize(iv.lo) && stored <= quantize(iv.hi)) continue;
          if (r.violations++ == 0) r.worst_x = x, r.worst_y = y, r.worst_z = z;
        }
  return r;
}

}  // namespace vct::cmp
