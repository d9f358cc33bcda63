// White furnace: a closed sphere, Lambertian albedo rho, uniform emission Le, camera inside.
// Every ray hits the wall, so L = Le * sum_k rho^k = Le / (1 - rho) (up to rho^(max_depth+1)).
// Judged with the sample-split variance: |mean - expected| < 4 sigma of the image mean, where
// sigma^2 = sum of the per-pixel variances / pixels^2 (pixels are independent).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

struct ImageStats {
  vec3 mean{0.0f};
  vec3 sigma{0.0f};  // standard error of `mean`
};

ImageStats image_mean(const Accumulator& acc, Aov aov) {
  const Image m = acc.mean(aov), v = acc.variance(aov);
  ImageStats s;
  const double n = double(m.width) * m.height;
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, var = 0.0;
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) {
        sum += double(m.at(x, y, c));
        var += double(v.at(x, y, c));
      }
    s.mean[c] = float(sum / n);
    s.sigma[c] = float(std::sqrt(var) / n);
  }
  return s;
}

Scene furnace(float rho, float le, bool double_sided) {
  Scene s;
  // Double-sided spheres are built outward so that emission from the back face is exercised.
  const uint32_t m = test::add_material(s, test::lambertian(vec3(rho), vec3(le), double_sided));
  test::add_icosphere(s, vec3(0.0f), 1.0f, 2, !double_sided, m);
  s.camera = test::look_at(vec3(0.1f, -0.05f, 0.0f), vec3(0.3f, 0.2f, -1.0f), vec3(0, 1, 0), 1.2f);
  test::finish(s);
  return s;
}

struct FurnaceCase {
  float rho;
  float le;
  bool double_sided;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(Furnace, RadianceIsLeOverOneMinusRho) {
  const FurnaceCase fc = GetParam();
  const Scene scene = furnace(fc.rho, fc.le, fc.double_sided);
  PtSettings ps;
  ps.width = 24;
  ps.height = 24;
  ps.max_depth = 200;
  ps.rr_start_depth = 3;
  ps.seed = 7;
  set_thread_count(0);
  const PathTracer pt(scene, ps);
  Accumulator acc(ps.width, ps.height);
  const RayCounts rays = pt.render(acc, 64);
  EXPECT_EQ(rays.nonfinite_samples, 0u);

  const float expected = fc.le / (1.0f - fc.rho);
  const ImageStats full = image_mean(acc, kFull);
  for (int c = 0; c < 3; ++c) {
    // The test must have power: the standard error has to be well below 1 %.
    EXPECT_LT(full.sigma[c], 0.005f * expected);
    EXPECT_NEAR(full.mean[c], expected, 4.0f * full.sigma[c]) << "channel " << c << " sigma " << full.sigma[c];
  }
  std::printf("[furnace rho=%.2f Le=%.1f %s] full = %.5f (expected %.5f), error %.2f sigma, sigma %.5f\n", double(fc.rho),
              double(fc.le), fc.double_sided ? "double-sided" : "one-sided", double(full.mean.r), double(expected),
              double((full.mean.r - expected) / full.sigma.r), double(full.sigma.r));

  // Emission is Le exactly at the first hit; no spot lights, so no direct term.
  const ImageStats emission = image_mean(acc, kEmission);
  EXPECT_FLOAT_EQ(emission.mean.r, fc.le);
  EXPECT_EQ(image_mean(acc, kDirect).mean, vec3(0.0f));
  // One diffuse bounce of the emitted light: rho * Le; no specular lobe.
  const ImageStats one = image_mean(acc, kIndirectDiffuse);
  EXPECT_NEAR(one.mean.g, fc.rho * fc.le, 4.0f * one.sigma.g + 1e-6f);
  EXPECT_EQ(image_mean(acc, kIndirectSpecular).mean, vec3(0.0f));
}

INSTANTIATE_TEST_SUITE_P(Cases, Furnace,
                         ::testing::Values(FurnaceCase{0.5f, 1.0f, false}, FurnaceCase{0.8f, 0.5f, false},
                                           FurnaceCase{0.3f, 2.0f, true}));

TEST(Furnace, OneSidedEmitterSeenFromBehindIsDark) {
  // Outward-wound, one-sided sphere seen from inside: only back faces; nothing is emitted
  // toward the camera and nothing reaches any wall, so every AOV is exactly zero.
  Scene s;
  const uint32_t m = test::add_material(s, test::lambertian(vec3(0.5f), vec3(1.0f), false));
  test::add_icosphere(s, vec3(0.0f), 1.0f, 1, false, m);
  s.camera = test::look_at(vec3(0.0f), vec3(0, 0, -1), vec3(0, 1, 0), 1.0f);
  test::finish(s);
  PtSettings ps;
  ps.width = ps.height = 8;
  const PathTracer pt(s, ps);
  Accumulator acc(8, 8);
  pt.render(acc, 4);
  EXPECT_EQ(image_mean(acc, kFull).mean, vec3(0.0f));
}

TEST(Furnace, SampleSplitVarianceMatchesSpreadOverSeeds) {
  // The written variance must predict the actual scatter of independent renders: 40 seeds of a
  // small furnace, the variance of their image means vs the mean predicted variance. The ratio
  // of an unbiased estimate over 39 degrees of freedom (chi^2_39 / 39) lies in [0.45, 1.75] with
  // probability > 99.5 % (the seeds are fixed, so the test is deterministic).
  const Scene scene = furnace(0.6f, 1.0f, false);
  PtSettings ps;
  ps.width = ps.height = 8;
  ps.max_depth = 100;
  constexpr int kSeeds = 40;
  std::vector<double> means;
  double predicted = 0.0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    ps.seed = uint32_t(seed);
    const PathTracer pt(scene, ps);
    Accumulator acc(ps.width, ps.height);
    pt.render(acc, 8);
    const ImageStats st = image_mean(acc, kFull);
    means.push_back(double(st.mean.g));
    predicted += double(st.sigma.g) * double(st.sigma.g) / kSeeds;
  }
  double m = 0.0, v = 0.0;
  for (double x : means) m += x / kSeeds;
  for (double x : means) v += (x - m) * (x - m) / (kSeeds - 1);
  std::printf("[variance check] spread of image means %.3e, predicted %.3e, ratio %.2f\n", v, predicted, v / predicted);
  EXPECT_GT(v / predicted, 0.45);
  EXPECT_LT(v / predicted, 1.75);
}

}  // namespace
}  // namespace vct::pt
