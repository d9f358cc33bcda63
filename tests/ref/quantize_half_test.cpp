// quantize_half (stages/reduction.cpp) rounds on the float's bits; it must give the bits of the
// spacing formula it replaced (libm frexp/ldexp/nearbyint), which reduction_test pins by hand and
// against glm's packHalf2x16. Checked here over a dense sample of all floats and every float of
// the binades where the rounding position moves (the binary16 subnormals); the whole 2^32 was
// checked once when it was written (docs/performance.md, "Validate at grid 256").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "stages/reduction.h"

namespace vct {
namespace {

// The former implementation: round |v| to the binary16 spacing at |v|, ties to even.
float spacing_formula(float v) {
  if (!std::isfinite(v) || v == 0.0f) return v;
  const float a = std::abs(v);
  if (a >= 65520.0f) return std::copysign(INFINITY, v);
  int e = 0;
  std::frexp(a, &e);
  const int ulp_exp = std::max(e - 1 - 10, -24);
  const float scaled = std::ldexp(a, -ulp_exp);
  return std::copysign(std::ldexp(std::nearbyint(scaled), ulp_exp), v);
}

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

float from_bits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// Bit patterns of the results (NaN payloads and the sign of zero included); the first mismatch.
::testing::AssertionResult same_as_formula(uint32_t u) {
  const float f = from_bits(u);
  if (bits(quantize_half(f)) == bits(spacing_formula(f))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "input bits 0x" << std::hex << u << ": got 0x" << bits(quantize_half(f))
                                       << ", the formula gives 0x" << bits(spacing_formula(f));
}

TEST(QuantizeHalf, EveryFloatOfAStride) {
  // A prime stride: 16.7 M inputs over every exponent, both signs, NaNs and infinities.
  for (uint64_t u = 0; u < (uint64_t(1) << 32); u += 257) ASSERT_TRUE(same_as_formula(uint32_t(u)));
}

// All 2^32 floats (~1 min): run by hand with --gtest_also_run_disabled_tests.
TEST(QuantizeHalf, DISABLED_EveryFloat) {
  for (uint64_t u = 0; u < (uint64_t(1) << 32); ++u) ASSERT_TRUE(same_as_formula(uint32_t(u)));
}

TEST(QuantizeHalf, EveryFloatWhereTheRoundingPositionMoves) {
  // |v| in [2^-26, 2^-13): below 2^-25 everything rounds to 0, and through the binary16 subnormals
  // the dropped bits grow from 13 to 24; every seventh float of both signs.
  for (uint32_t sign : {0u, 0x80000000u})
    for (uint32_t u = bits(0x1p-26f); u < bits(0x1p-13f); u += 7) ASSERT_TRUE(same_as_formula(sign | u));
}

TEST(QuantizeHalf, EveryTieAndItsNeighbours) {
  // In every binade and both signs: each value halfway between two binary16 values (and the
  // floats one below and above it), for the first and last 1024 steps of the binade.
  for (uint32_t sign : {0u, 0x80000000u})
    for (uint32_t exponent = 0; exponent < 255; ++exponent)
      for (uint32_t step = 0; step < (1u << 10); ++step)
        for (uint32_t high : {0u, 0x7FE000u - (step << 13)})
          for (int delta : {-1, 0, 1}) {
            const uint32_t mantissa = ((high + (step << 13)) | 0x1000u) + uint32_t(delta);
            ASSERT_TRUE(same_as_formula(sign | (exponent << 23) | (mantissa & 0x7FFFFFu)));
          }
}

TEST(QuantizeHalf, SpecialValues) {
  EXPECT_TRUE(std::isnan(quantize_half(NAN)));
  EXPECT_EQ(quantize_half(INFINITY), INFINITY);
  EXPECT_EQ(quantize_half(-INFINITY), -INFINITY);
  EXPECT_TRUE(std::signbit(quantize_half(-0.0f)));
  EXPECT_TRUE(std::signbit(quantize_half(-0x1p-26f)));      // rounds to -0
  EXPECT_EQ(quantize_half(0x1p-25f), 0.0f);                 // the tie at half the smallest: to even 0
  EXPECT_EQ(quantize_half(std::nextafter(0x1p-25f, 1.0f)), 0x1p-24f);
  EXPECT_EQ(quantize_half(0x1.ffcp-15f), 0x1p-14f);  // 1023.5 x 2^-24: the tie goes to even 1024
  EXPECT_EQ(quantize_half(65519.996f), 65504.0f);
  EXPECT_EQ(quantize_half(std::numeric_limits<float>::denorm_min()), 0.0f);
}

}  // namespace
}  // namespace vct
