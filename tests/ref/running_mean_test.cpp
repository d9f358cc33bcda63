// The racy running mean's interval (freedoms/reduction_interval.h): every order and every non-empty
// subset of a voxel's fragments, run through the binary16 running mean, lands inside it, and
// its ends are within the stated ulps of values those runs reach.
#include <algorithm>
#include <gtest/gtest.h>
#include <random>

#include "freedoms/reduction_interval.h"
#include "stages/reduction.h"
#include "stages/running_mean.h"

namespace vct {
namespace {

TEST(RunningMean, SequentialHandComputed) {
  // 0.25 then 0.75: s1 = 0.25, s2 = (0.25 + 0.75)/2 = 0.5; then 1.0: (0.5*2 + 1)/3 = 2/3 -> binary16
  // 0.66650390625 (nearest of the 2^-11 spaced values around 2/3).
  EXPECT_FLOAT_EQ(running_mean_half_sequential({0.25f, 0.75f}), 0.5f);
  EXPECT_FLOAT_EQ(running_mean_half_sequential({0.25f, 0.75f, 1.0f}), 0.66650390625f);
  // Order matters once rounding does: the racy mean is not the exact mean.
  EXPECT_FLOAT_EQ(running_mean_half_sequential({1.0f}), 1.0f);
}

TEST(RunningMean, IntervalEndsAreTheRoundedExtremesPlusTwoUlps) {
  const ValueInterval iv = running_mean_interval({0.25f, 0.5f, 1.0f});
  // binary16 ulp at 0.25 is 2^-12, at 1.0 it is 2^-10.
  EXPECT_FLOAT_EQ(iv.lo, 0.25f - 2.0f * 0x1p-12f);
  EXPECT_FLOAT_EQ(iv.hi, 1.0f + 2.0f * 0x1p-10f);
  const ValueInterval none = running_mean_interval({});
  EXPECT_EQ(none.lo, 0.0f);
  EXPECT_EQ(none.hi, 0.0f);
}

// Every permutation of every non-empty subset (lost updates) of random fragment sets of up to 5
// values: all inside the interval; the interval's ends are reached within 2 ulps.
TEST(RunningMean, EveryOrderAndSubsetInsideTheInterval) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(0.0f, 3.0f);
  for (int trial = 0; trial < 200; ++trial) {
    const size_t m = 1 + size_t(trial % 5);
    std::vector<float> x(m);
    for (float& v : x) v = u(rng);
    const ValueInterval iv = running_mean_interval(x);
    float seen_lo = 1e30f, seen_hi = -1e30f;
    for (size_t mask = 1; mask < (size_t(1) << m); ++mask) {
      std::vector<float> sub;
      for (size_t i = 0; i < m; ++i)
        if (mask & (size_t(1) << i)) sub.push_back(x[i]);
      std::sort(sub.begin(), sub.end());
      do {
        const float s = running_mean_half_sequential(sub);
        ASSERT_GE(s, iv.lo);
        ASSERT_LE(s, iv.hi);
        seen_lo = std::min(seen_lo, s), seen_hi = std::max(seen_hi, s);
      } while (std::next_permutation(sub.begin(), sub.end()));
    }
    // Tight: the singletons reach h(min) and h(max); the interval adds 2 binary16 ulps (<= 2^-9
    // at values below 2, 2^-8 below 4).
    EXPECT_LE(seen_lo - iv.lo, 2.0f * 0x1p-9f);
    EXPECT_LE(iv.hi - seen_hi, 2.0f * 0x1p-8f);
    EXPECT_EQ(seen_lo, quantize_half(*std::min_element(x.begin(), x.end())));
  }
}

// A stored value outside [min, max] of the fragments (a real fault, e.g. a wrong weight) is outside.
TEST(RunningMean, ValueBeyondTheFragmentsIsOutside) {
  const ValueInterval iv = running_mean_interval({0.2f, 0.4f});
  EXPECT_GE(0.3f, iv.lo);  // the exact mean is one of the values the interval admits
  EXPECT_LE(0.3f, iv.hi);
  EXPECT_GT(0.41f, iv.hi);
  EXPECT_LT(0.19f, iv.lo);
}

TEST(RunningMean, AddedLightMovesBothEndsAndOneUlpOutward) {
  // Voxel (0,0,0) reduced to [0.5, 0.75], voxel (1,0,0) empty; 0.25 added to each. Occupied:
  // [0.75 - 2^-11, 1.0 + 2^-10] (binary16 spacing is 2^-11 in [0.5, 1), 2^-10 in [1, 2)).
  // Empty: [0.25 - 2^-12, 0.25 + 2^-12] (spacing 2^-12 in [0.25, 0.5)), alpha still 0.
  Volume lo(2, 1, 1, 4), hi(2, 1, 1, 4);
  lo.set_rgba(0, 0, 0, vec4(0.5f, 0.5f, 0.5f, 1.0f));
  hi.set_rgba(0, 0, 0, vec4(0.75f, 0.75f, 0.75f, 1.0f));
  add_light_to_interval({{ivec3(0, 0, 0), vec3(0.25f)}, {ivec3(1, 0, 0), vec3(0.25f, 0.0f, 0.0f)}, {ivec3(5, 0, 0), vec3(1.0f)}},
                        lo, hi);
  EXPECT_EQ(lo.voxel(0, 0, 0)[0], 0.75f - 0x1p-11f);
  EXPECT_EQ(hi.voxel(0, 0, 0)[0], 1.0f + 0x1p-10f);
  EXPECT_EQ(lo.voxel(1, 0, 0)[0], 0.25f - 0x1p-12f);
  EXPECT_EQ(hi.voxel(1, 0, 0)[0], 0.25f + 0x1p-12f);
  EXPECT_EQ(hi.voxel(1, 0, 0)[3], 0.0f);
  // Nothing added in G: the empty voxel's interval there is the smallest ulp around 0.
  EXPECT_LE(hi.voxel(1, 0, 0)[1], 0x1p-23f);
}

}  // namespace
}  // namespace vct
