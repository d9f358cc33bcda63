// The alias table picks each index with exactly its weight's share: counted over a uniform grid
// of u (every pick the float u can make at 2^-20 spacing), against hand-computed probabilities.
#include <gtest/gtest.h>

#include <vector>

#include "pt/alias_table.h"

namespace vct::pt {
namespace {

std::vector<double> pick_frequencies(const AliasTable& t, int bits) {
  const int64_t steps = int64_t(1) << bits;
  std::vector<double> f(t.size(), 0.0);
  for (int64_t k = 0; k < steps; ++k) f[t.sample(float(double(k) / double(steps)))] += 1.0 / double(steps);
  return f;
}

TEST(AliasTable, PicksByWeightHandCounted) {
  const AliasTable t({1.0, 2.0, 3.0, 4.0});
  ASSERT_EQ(t.size(), 4u);
  const std::vector<double> f = pick_frequencies(t, 20);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(t.pmf(i), float(i + 1) / 10.0f);
    EXPECT_NEAR(f[i], double(i + 1) / 10.0, 2.0 / double(1 << 20)) << i;
  }
}

TEST(AliasTable, UnevenWeightsAndZeros) {
  // Odd size (u n not exact), a dominant entry, a zero and a tiny one.
  const std::vector<double> w = {1000.0, 0.0, 1.0, 3.5, 0.01, 7.0, 2.0};
  double total = 0.0;
  for (double x : w) total += x;
  const AliasTable t(w);
  const std::vector<double> f = pick_frequencies(t, 22);
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_NEAR(t.pmf(i), w[i] / total, 1e-7);
    EXPECT_NEAR(f[i], w[i] / total, 8.0 / double(1 << 22)) << i;
  }
  EXPECT_EQ(f[1], 0.0);  // never picks a zero weight
}

TEST(AliasTable, EndsOfTheUnitInterval) {
  const AliasTable t({1.0, 1.0, 1.0});
  EXPECT_EQ(t.sample(0.0f), 0u);
  EXPECT_EQ(t.sample(0.99999994f), 2u);  // largest float below 1
}

TEST(AliasTable, EmptyWithoutPositiveWeight) {
  EXPECT_TRUE(AliasTable(std::vector<double>{}).empty());
  EXPECT_TRUE(AliasTable({0.0, 0.0}).empty());
}

}  // namespace
}  // namespace vct::pt
