// Voxel reductions: exact mean independent of order, the fixed-point scheme by hand, the CAS
// interval against every order, storage quantization.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "freedoms/voxel_freedoms.h"
#include "shared/voxel_fixed_point.h"
#include "stage_test_scene.h"
#include "stages/inject.h"
#include "stages/reduction.h"

namespace vct {
namespace {

TEST(Reduction, ExactMeanDoesNotDependOnOrder) {
  std::vector<float> v = {1e-3f, 3.0f, 0.1f, 7.5f, 1e-7f, 0.3333f, 2.0f, 5e4f, 0.7f};
  const float m = exact_mean(v);
  std::mt19937 rng(3);
  for (int i = 0; i < 50; ++i) {
    std::shuffle(v.begin(), v.end(), rng);
    EXPECT_EQ(exact_mean(v), m);
  }
  double sum = 0.0;
  for (float x : v) sum += double(x);
  EXPECT_NEAR(double(m), sum / 9.0, 1e-3);
  EXPECT_EQ(exact_mean({0.25f, 0.75f}), 0.5f);
}

TEST(Reduction, FixedPointByHand) {
  EXPECT_EQ(sh::fixed_point_encode(0.5f), 8192u);
  EXPECT_EQ(sh::fixed_point_encode(0.25f), 4096u);
  EXPECT_EQ(sh::fixed_point_encode(-3.0f), 0u);
  EXPECT_EQ(sh::fixed_point_encode(5000.0f), 16777216u);  // clamped to 1024
  EXPECT_EQ(sh::fixed_point_encode(1.0f / 65536.0f), 0u);  // 0.25 -> rounds down
  EXPECT_EQ(sh::fixed_point_encode(3.0f / 65536.0f), 1u);  // 0.75 -> 1
  // (8192 + 4096 + 1) / 2 = 6144 -> 0.375
  EXPECT_EQ(fixed_point_mean({0.5f, 0.25f}), 0.375f);
  EXPECT_EQ(fixed_point_mean({3.0f / 65536.0f, 0.0f, 0.0f}), 0.0f);  // (1 + 1) / 3 = 0
  EXPECT_EQ(fixed_point_mean({3.0f / 65536.0f, 3.0f / 65536.0f, 0.0f}), 1.0f / 16384.0f);  // (2 + 1) / 3 = 1
  // Order-independent by construction (integer sums).
  EXPECT_EQ(fixed_point_mean({0.1f, 7.0f, 0.3f}), fixed_point_mean({7.0f, 0.3f, 0.1f}));
  EXPECT_NEAR(fixed_point_mean({0.1f, 7.0f, 0.3f}), 7.4f / 3.0f, 1.0f / 16384.0f);
}

TEST(Reduction, CasStepMatchesOpenGLInsights) {
  // First fragment: uint(0.5 * 255) = 127. Second (count 1): uint((127 + 255) / 2) = 191.
  EXPECT_EQ(cas_step(0, 0, 0.5f * 255.0f), 127);
  EXPECT_EQ(cas_step(127, 1, 255.0f), 191);
  EXPECT_FLOAT_EQ(cas_sequential({0.5f, 1.0f}), 191.0f / 255.0f);
  EXPECT_FLOAT_EQ(cas_sequential({1.0f, 0.5f}), 191.0f / 255.0f);  // (255 + 127.5) / 2 = 191.25
  EXPECT_FLOAT_EQ(cas_sequential({2.0f}), 1.0f);  // clamped to [0,1]
}

void check_interval_covers_all_orders(std::vector<float> v) {
  std::sort(v.begin(), v.end());
  const CasInterval exact = cas_interval(v), bound = cas_interval_bound(v);
  float lo = 2.0f, hi = -1.0f;
  do {
    const float r = cas_sequential(v);
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    EXPECT_GE(r, exact.lo);
    EXPECT_LE(r, exact.hi);
    EXPECT_GE(r, bound.lo);
    EXPECT_LE(r, bound.hi);
  } while (std::next_permutation(v.begin(), v.end()));
  // The enumeration is tight up to the division slack: its ends are within one step of what
  // IEEE-exact orders reach.
  EXPECT_LE(hi - lo, exact.hi - exact.lo);
  EXPECT_LE(exact.hi - hi, 1.0f / 255.0f + 1e-6f);
  EXPECT_LE(lo - exact.lo, 1.0f / 255.0f + 1e-6f);
  EXPECT_LE(exact.lo, exact.hi);
  EXPECT_GE(exact.lo, bound.lo);
  EXPECT_LE(exact.hi, bound.hi);
}

TEST(Reduction, CasIntervalContainsEveryOrder) {
  check_interval_covers_all_orders({0.5f});
  check_interval_covers_all_orders({0.1f, 0.9f});
  check_interval_covers_all_orders({0.0f, 1.0f, 0.33f});
  check_interval_covers_all_orders({0.2f, 0.21f, 0.8f, 0.95f, 0.5f});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int t = 0; t < 10; ++t) {
    std::vector<float> v(size_t(3 + t % 5));
    for (float& x : v) x = u(rng);
    check_interval_covers_all_orders(v);
  }
  // Order really matters: (0, 1, 1) -> 0,127,169 vs (1, 1, 0) -> 255,255,170.
  EXPECT_NE(cas_sequential({0.0f, 1.0f, 1.0f}), cas_sequential({1.0f, 1.0f, 0.0f}));
}

TEST(Reduction, CasBoundForManyFragments) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> v(40);
  for (float& x : v) x = u(rng);
  const CasInterval b = cas_interval(v);  // above the exact limit: the bound
  for (int t = 0; t < 200; ++t) {
    std::shuffle(v.begin(), v.end(), rng);
    const float r = cas_sequential(v);
    EXPECT_GE(r, b.lo);
    EXPECT_LE(r, b.hi);
  }
}

TEST(Reduction, HalfQuantizationRoundsToNearestEven) {
  EXPECT_EQ(quantize_half(1.0f), 1.0f);
  EXPECT_EQ(quantize_half(1.0f / 3.0f), 0.333251953125f);
  EXPECT_EQ(quantize_half(1.0f + 1.0f / 2048.0f), 1.0f);                   // tie -> even
  EXPECT_EQ(quantize_half(1.0f + 3.0f / 2048.0f), 1.0f + 2.0f / 1024.0f);  // tie -> even (up)
  EXPECT_EQ(quantize_half(65504.0f), 65504.0f);
  EXPECT_EQ(quantize_half(65519.0f), 65504.0f);
  EXPECT_TRUE(std::isinf(quantize_half(65520.0f)));
  EXPECT_EQ(quantize_half(std::ldexp(1.0f, -24)), std::ldexp(1.0f, -24));     // smallest subnormal
  EXPECT_EQ(quantize_half(std::ldexp(1.0f, -26)), 0.0f);
  EXPECT_EQ(quantize_half(std::ldexp(3.0f, -25)), std::ldexp(2.0f, -24));     // 1.5 ulp -> 2 (even)
  EXPECT_EQ(quantize_half(-2.5f), -2.5f);
  // Against glm's packHalf on values away from ties.
  for (float x : {0.1f, 0.7f, 3.14159f, 123.456f, 1e-3f, 7e-6f})
    EXPECT_EQ(quantize_half(x), glm::unpackHalf2x16(glm::packHalf2x16(vec2(x))).x) << x;
}

TEST(Reduction, Unorm8) {
  EXPECT_EQ(quantize_unorm8(0.5f), 128.0f / 255.0f);
  EXPECT_EQ(quantize_unorm8(2.0f), 1.0f);
  EXPECT_EQ(quantize_unorm8(-1.0f), 0.0f);
}

TEST(Reduction, InjectTwoFragmentsInOneVoxel) {
  // Two emissive triangles crossing voxel (1,1,1) of a 4^3 grid; no lights: the voxel holds the
  // mean emission, opacity 1.
  Scene s;
  const uint32_t a = test::add_material(s, vec3(0.5f), vec3(1.0f, 0.0f, 0.25f));
  const uint32_t b = test::add_material(s, vec3(0.5f), vec3(0.5f, 2.0f, 0.75f));
  test::add_triangle(s, {1.2f, 1.2f, 1.5f}, {1.8f, 1.2f, 1.5f}, {1.2f, 1.8f, 1.5f}, a);
  test::add_triangle(s, {1.5f, 1.2f, 1.2f}, {1.5f, 1.8f, 1.2f}, {1.5f, 1.2f, 1.8f}, b);
  s.volume.origin = vec3(0.0f);
  s.volume.size = 4.0f;
  const Voxelization v = voxelize_conservative(s, 4);
  ASSERT_EQ(v.fragments.size(), 2u);
  for (Reduction r : {Reduction::ExactMean, Reduction::FixedPoint}) {
    VctSettings st;
    st.reduction = r;
    st.storage = VoxelStorage::Rgba16f;
    const VoxelGrid g = inject_and_reduce(s, v, {}, st);
    EXPECT_EQ(g.radiance.rgba(1, 1, 1), vec4(0.75f, 1.0f, 0.5f, 1.0f));
    EXPECT_EQ(*g.fragments.voxel(1, 1, 1), 2.0f);
    EXPECT_EQ(g.radiance.rgba(0, 0, 0), vec4(0.0f));
    EXPECT_TRUE(g.cas_lo.data.empty());
  }
  VctSettings st;
  st.reduction = Reduction::CasRgba8;
  st.storage = VoxelStorage::Rgba8;
  const VoxelGrid g = judged_voxels(s, v, {}, st);  // the CAS interval is the judge's (freedoms/)
  const vec4 lo = g.cas_lo.rgba(1, 1, 1), hi = g.cas_hi.rgba(1, 1, 1), r = g.radiance.rgba(1, 1, 1);
  // Red: (255, 127.5) either order -> 191; green: (0, 255) -> 127; blue (63.75, 191.25) -> 127.
  EXPECT_EQ(r, vec4(191.0f / 255.0f, 127.0f / 255.0f, 127.0f / 255.0f, 1.0f));
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(lo[c], r[c]);
    EXPECT_GE(hi[c], r[c]);
  }
}

}  // namespace
}  // namespace vct
