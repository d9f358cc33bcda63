// Metrics against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/metrics.h"
#include "compare/tolerance.h"

namespace vct::cmp {
namespace {

Image constant(int w, int h, float v) { return Image(w, h, 3, v); }

TEST(Metrics, HandComputedMseBiasRelMse) {
  const Image ref = constant(4, 4, 0.5f);
  Image test = ref;
  test.at(0, 0, 0) = 1.5f;  // one channel of one pixel off by +1
  const ImageMetrics m = image_metrics(test, ref);
  const double n = 4 * 4 * 3;
  EXPECT_NEAR(m.mse, 1.0 / n, 1e-12);
  EXPECT_NEAR(m.mean_bias, 1.0 / n, 1e-12);
  EXPECT_NEAR(m.rel_mse, (1.0 / (0.25 + kRelMseEpsilon)) / n, 1e-9);
  EXPECT_NEAR(m.relative_bias, 1.0 / (0.5 * n), 1e-12);
  EXPECT_DOUBLE_EQ(m.max_abs, 1.0);
}

TEST(Metrics, SsimIsOneForIdenticalAndDropsForNoise) {
  Image a(32, 32, 1);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) a.at(x, y, 0) = float((x / 4 + y / 4) % 2);
  EXPECT_NEAR(ssim(a, a), 1.0, 1e-9);
  Image b = a;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) b.at(x, y, 0) = 1.0f - a.at(x, y, 0);  // inverted pattern
  EXPECT_LT(ssim(b, a), 0.0);  // anti-correlated structure: SSIM negative
}

TEST(Tolerance, HalfUlpMatchesBinary16) {
  EXPECT_DOUBLE_EQ(half_ulp(1.0), std::ldexp(1.0, -10));
  EXPECT_DOUBLE_EQ(half_ulp(1.5), std::ldexp(1.0, -10));
  EXPECT_DOUBLE_EQ(half_ulp(2.0), std::ldexp(1.0, -9));
  EXPECT_DOUBLE_EQ(half_ulp(1e-6), std::ldexp(1.0, -24));  // subnormal spacing
}

TEST(Tolerance, MipBoundGrowsOneRoundingPerLevel) {
  const VoxelModel fp = voxel_model("rgba8", "fixed_point");
  EXPECT_EQ(fp.name, "fixed-point-exact+shading");
  const double base = std::ldexp(1.0, -14) + 1.0 / 255.0;
  EXPECT_NEAR(fp.abs, base, 1e-12);
  const MipBound b2 = mip_bound(fp, "rgba8", 2, false);
  EXPECT_NEAR(b2.abs, base + 2.0 / 255.0, 1e-12);  // one 8-bit rounding per level
  const MipBound a2 = mip_bound(fp, "rgba8", 2, true);
  EXPECT_NEAR(a2.abs, 4.0 * base + 3.0 / 255.0, 1e-12);  // 2*(2*base + 1/255) + 1/255
}

}  // namespace
}  // namespace vct::cmp
