#include "stages/reduction.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "shared/voxel_fixed_point.h"

namespace vct {

float exact_mean(std::vector<float> values) {
  if (values.empty()) return 0.0f;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (float v : values) sum += double(v);
  return float(sum / double(values.size()));
}

float fixed_point_mean(const std::vector<float>& values) {
  uint32_t sum = 0;
  for (float v : values) sum += sh::fixed_point_encode(v);  // wraps modulo 2^32 like the GPU
  return sh::fixed_point_resolve(sum, uint32_t(values.size()));
}

float reduction_input(float v, Reduction r) {
  switch (r) {
    case Reduction::FixedPoint: return std::min(std::max(v, 0.0f), sh::FIXED_POINT_MAX);
    case Reduction::CasRgba8: return std::clamp(v, 0.0f, 1.0f);
    case Reduction::ExactMean:
    default: return v;
  }
}

namespace {

float cas_input(float v) { return std::clamp(v, 0.0f, 1.0f) * 255.0f; }

// The GPU divides with up to 2.5 ulp error (GLSL 4.50), so a quotient this close to an integer
// may land on either side of it.
constexpr double kDivisionSlack = 1e-6;

double cas_quotient(int s, int count, float x) {
  return double((float(s) * float(count) + x) / float(count + 1));
}

}  // namespace

int cas_step(int s, int count, float x) { return int(cas_quotient(s, count, x)); }

float cas_sequential(const std::vector<float>& values) {
  int s = 0;
  for (size_t i = 0; i < values.size(); ++i) s = cas_step(s, int(i % 256), cas_input(values[i])) & 0xFF;
  return float(s) / 255.0f;
}

CasInterval cas_interval_bound(const std::vector<float>& values) {
  // With A_c the exact mean of the first c inputs, induction on c gives A_c - (c+1)/2 < s_c <= A_c
  // for truncation (e_{c+1} < c/(c+1) e_c + 1); each division may add delta, hence m*delta slack.
  const size_t m = values.size();
  if (m == 0) return {};
  if (m >= 256) return {0.0f, 1.0f};  // the 8-bit count wraps: anything is possible
  double a = 0.0;
  for (float v : values) a += double(cas_input(v));
  a /= double(m);
  const double slack = double(m) * kDivisionSlack * 256.0;
  const double lo = std::max(0.0, std::floor(a - 0.5 * double(m + 1) - slack));
  const double hi = std::min(255.0, std::floor(a + slack));
  return {float(lo) / 255.0f, float(hi) / 255.0f};
}

CasInterval cas_interval(const std::vector<float>& values) {
  const size_t m = values.size();
  if (m == 0) return {};
  if (m > kCasExactLimit) return cas_interval_bound(values);
  // reach[mask] = stored values possible after exactly the fragments in mask.
  std::vector<std::bitset<256>> reach(size_t(1) << m);
  reach[0].set(0);
  std::vector<float> x(m);
  for (size_t i = 0; i < m; ++i) x[i] = cas_input(values[i]);
  for (size_t mask = 0; mask < reach.size(); ++mask) {
    if (reach[mask].none()) continue;
    const int count = __builtin_popcountll(mask);
    for (size_t j = 0; j < m; ++j) {
      if (mask & (size_t(1) << j)) continue;
      std::bitset<256>& next = reach[mask | (size_t(1) << j)];
      for (size_t s = reach[mask]._Find_first(); s < 256; s = reach[mask]._Find_next(s)) {
        const double q = cas_quotient(int(s), count, x[j]);
        const double f = std::floor(q), tol = kDivisionSlack * std::max(q, 1.0);
        next.set(size_t(f));
        if (q - f < tol && f >= 1.0) next.set(size_t(f - 1.0));
        if (f + 1.0 - q < tol && f < 255.0) next.set(size_t(f + 1.0));
      }
    }
  }
  const std::bitset<256>& last = reach.back();
  int lo = 255, hi = 0;
  for (int s = 0; s < 256; ++s)
    if (last.test(size_t(s))) {
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  return {float(lo) / 255.0f, float(hi) / 255.0f};
}

float quantize_unorm8(float v) { return std::nearbyint(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f; }

// Round to nearest even on the float's bits (no libm: frexpf/scalbnf were 11 % of validate's
// comparison at grid 256, docs/performance.md). Bit-identical to the spacing formula
// round(|v| / 2^k) 2^k, k = max(e - 10, -24) for |v| in [2^e, 2^(e+1)), checked against it in
// tests/ref/quantize_half_test.cpp.
float quantize_half(float v) {
  if (!std::isfinite(v) || v == 0.0f) return v;
  const float a = std::abs(v);
  if (a >= 65520.0f) return std::copysign(INFINITY, v);  // beyond max half + half an ulp
  uint32_t u;
  std::memcpy(&u, &a, 4);
  const int e = int(u >> 23) - 127;  // a is in [2^e, 2^(e+1)); float subnormals give e = -127
  if (e >= -14) {
    // A binary16 normal: drop the low 13 of the 23 mantissa bits, ties to even (a carry into the
    // exponent is the next binade's first value, as it should be).
    u = (u + 0x0FFFu + ((u >> 13) & 1u)) & ~0x1FFFu;
    float r;
    std::memcpy(&r, &u, 4);
    return std::copysign(r, v);
  }
  if (e < -25) return std::copysign(0.0f, v);  // below half the smallest subnormal 2^-24
  // A binary16 subnormal: the multiple q of 2^-24 nearest the 24-bit significand m 2^(e-23),
  // i.e. m >> d rounded with d = -1 - e bits dropped (14..24), ties to even.
  const uint32_t m = (u & 0x7FFFFFu) | 0x800000u;
  const int d = -1 - e;
  uint32_t q = m >> d;
  const uint32_t rest = m & ((1u << d) - 1u), half = 1u << (d - 1);
  if (rest > half || (rest == half && (q & 1u))) ++q;
  return std::copysign(float(q) * 0x1p-24f, v);  // exact: q <= 2^10
}

float quantize_storage(float v, VoxelStorage storage) {
  return storage == VoxelStorage::Rgba8 ? quantize_unorm8(v) : quantize_half(v);
}

}  // namespace vct
