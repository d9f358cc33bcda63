#include "stages/reduction.h"

#include <algorithm>
#include <bitset>
#include <cmath>

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

float quantize_half(float v) {
  if (!std::isfinite(v) || v == 0.0f) return v;
  const float a = std::abs(v);
  if (a >= 65520.0f) return std::copysign(INFINITY, v);  // beyond max half + half an ulp
  // Spacing of binary16 at |v|: 2^(e-10) for normals (e = exponent), 2^-24 for subnormals.
  int e = 0;
  std::frexp(a, &e);  // a = f * 2^e, f in [0.5, 1): exponent of a is e-1
  const int ulp_exp = std::max(e - 1 - 10, -24);
  const float scaled = std::ldexp(a, -ulp_exp);  // exact: power-of-two scaling
  return std::copysign(std::ldexp(std::nearbyint(scaled), ulp_exp), v);  // nearbyint: ties to even
}

float quantize_storage(float v, VoxelStorage storage) {
  return storage == VoxelStorage::Rgba8 ? quantize_unorm8(v) : quantize_half(v);
}

}  // namespace vct
