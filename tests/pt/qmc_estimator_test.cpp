// The scrambled Sobol sampler (pt.sampler = sobol, pt/path_sampler.h) keeps every statistical
// judgement built on the path tracer valid (docs/pathtracer.md "Variance"): its images are
// unbiased, its sample-split variance predicts the real scatter of its pixel means, and the bias
// test of compare/ (docs/compare.md "Variance-aware judgement") neither calls its noise bias nor
// misses a 5 % bias. And it pays: the variance of the mean is well below the independent
// sampler's at the same spp.
//
// Scene: a Lambertian floor lit by a one-sided emissive square above it, max_depth 1, so the
// floor's radiance is albedo/pi times the square's irradiance, which Lambert's polygon formula
// gives exactly at every pixel (each camera ray goes through its pixel centre).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "compare/bias.h"
#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/camera_ray.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

constexpr float kAlbedo = 0.5f, kLe = 4.0f, kLightY = 1.0f, kHalf = 0.5f;
constexpr int kSize = 32;

/// The floor and the light, optionally with a black blocker between them (a penumbra: the part
/// of the integrand that stratification helps least).
Scene floor_under_square(bool blocker) {
  Scene s;
  const uint32_t floor = test::add_material(s, test::lambertian(vec3(kAlbedo)));
  const uint32_t light = test::add_material(s, test::lambertian(vec3(0.0f), vec3(kLe)));
  test::add_quad(s, vec3(-3.0f, 0.0f, 3.0f), vec3(6.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -6.0f), floor);  // front +y
  test::add_quad(s, vec3(-kHalf, kLightY, -kHalf), vec3(2 * kHalf, 0.0f, 0.0f), vec3(0.0f, 0.0f, 2 * kHalf),
                 light);  // front -y
  if (blocker) {
    const uint32_t black = test::add_material(s, test::lambertian(vec3(0.0f), vec3(0.0f), true));
    test::add_quad(s, vec3(-0.1f, 0.5f, -0.6f), vec3(0.25f, 0.0f, 0.0f), vec3(0.0f, 0.0f, 1.2f), black);
  }
  // Below the light's plane, looking down at the floor: the camera never sees the light.
  s.camera = test::look_at(vec3(0.0f, 0.7f, 2.2f), vec3(0.0f, 0.0f, -0.3f), vec3(0, 1, 0), 0.7f);
  test::finish(s);
  return s;
}

/// Irradiance at floor point p from the square (Lambert: E = Le/2 sum_i angle_i n.(r_i x r_{i+1})/|..|).
double square_irradiance(const glm::dvec3& p) {
  const glm::dvec3 v[4] = {{-kHalf, kLightY, -kHalf}, {kHalf, kLightY, -kHalf}, {kHalf, kLightY, kHalf}, {-kHalf, kLightY, kHalf}};
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 a = glm::normalize(v[i] - p), b = glm::normalize(v[(i + 1) % 4] - p);
    const glm::dvec3 c = glm::cross(a, b);
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * c.y / glm::length(c);
  }
  return 0.5 * double(kLe) * std::abs(sum);
}

/// The exact image of the scene without blocker: albedo/pi E at each pixel centre's floor point.
Image exact_image(const Scene& s) {
  Image img(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Ray r = camera_ray(s.camera, kSize, kSize, float(x) + 0.5f, float(y) + 0.5f);
      if (!(r.dir.y < 0.0f)) continue;
      const double t = -double(r.org.y) / double(r.dir.y);
      const glm::dvec3 p = glm::dvec3(r.org) + t * glm::dvec3(r.dir);
      if (std::abs(p.x) > 3.0 || std::abs(p.z) > 3.0) continue;
      const float l = float(double(kAlbedo) / M_PI * square_irradiance(p));
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = l;
    }
  return img;
}

Accumulator render(const Scene& s, PtSampler sampler, uint32_t seed, uint32_t spp) {
  PtSettings ps;
  ps.width = ps.height = kSize;
  ps.max_depth = 1;
  ps.seed = seed;
  ps.sampler = sampler;
  const PathTracer pt(s, ps);
  Accumulator acc(kSize, kSize);
  pt.render(acc, spp);
  return acc;
}

cmp::BiasComponent judge(const Image& truth, const Accumulator& acc, float bias) {
  Image test = truth;
  for (float& v : test.data) v *= 1.0f + bias;
  cmp::StageSet vct;
  vct.images["image.final"] = test;
  const std::map<std::string, Image> pt{{"pt_full", acc.mean(kFull)}, {"pt_full_var", acc.variance(kFull)}};
  for (const cmp::BiasComponent& b : cmp::measure_bias(vct, pt))
    if (b.component == "full") return b;
  ADD_FAILURE() << "no full component";
  return {};
}

TEST(QmcEstimator, ExactImageIsWithinNoiseAndAFivePercentBiasIsCaught) {
  set_thread_count(0);
  const Scene s = floor_under_square(false);
  const Image truth = exact_image(s);
  for (PtSampler sampler : {PtSampler::Sobol, PtSampler::Independent}) {
    const Accumulator acc = render(s, sampler, 11u, 64);
    const cmp::BiasComponent same = judge(truth, acc, 0.0f);
    std::printf("[qmc %s] exact image: %.2f %% of pixels beyond 3 sigma (PT noise alone %.2f %%), mean bias z %.2f\n",
                to_string(sampler).c_str(), 100 * same.fraction_beyond_k_sigma, 100 * same.expected_fraction,
                same.mean_bias_z);
    ASSERT_TRUE(same.available && same.have_variance);
    EXPECT_FALSE(same.significant) << same.note;
    // The bias test's own allowance (docs/compare.md): 2 x P(|T_24| > 3) + 3 sqrt(P / n).
    const double n = double(kSize) * kSize;
    EXPECT_LT(same.fraction_beyond_k_sigma, 2 * same.expected_fraction + 3 * std::sqrt(same.expected_fraction / n));
    EXPECT_LT(std::abs(same.mean_bias_z), 5.0);
    EXPECT_TRUE(judge(truth, acc, 0.05f).significant) << "a 5 % bias must be caught";
  }
}

struct Spread {
  double z = 0.0;               // self-normalised sum of (spread - predicted) over pixels
  double predicted = 0.0;       // sum over pixels of the mean written variance
  double spread = 0.0;          // sum over pixels of the variance of the pixel mean over seeds
};

/// For each pixel: the variance of its mean over `seeds` independent renders (unbiased, seeds - 1
/// dof) against the mean of its written sample-split variance. Both estimate Var(pixel mean), so
/// d_p = spread_p - predicted_p has mean 0 and pixels are independent: z = sum d / sqrt(sum d^2)
/// is asymptotically standard normal whatever the distribution of the d_p (self-normalised sum).
Spread spread_over_seeds(const Scene& s, PtSampler sampler, int seeds, uint32_t spp) {
  std::vector<Image> means, vars;
  for (int k = 0; k < seeds; ++k) {
    const Accumulator acc = render(s, sampler, 100u + uint32_t(k), spp);
    means.push_back(acc.mean(kFull));
    vars.push_back(acc.variance(kFull));
  }
  Spread out;
  double sum_d = 0.0, sum_d2 = 0.0;
  for (size_t i = 0; i < means[0].data.size(); i += 3) {  // the red channel of each pixel
    double m = 0.0, w = 0.0, a = 0.0;
    for (int k = 0; k < seeds; ++k) m += double(means[size_t(k)].data[i]) / seeds;
    for (int k = 0; k < seeds; ++k) {
      const double e = double(means[size_t(k)].data[i]) - m;
      a += e * e / (seeds - 1);
      w += double(vars[size_t(k)].data[i]) / seeds;
    }
    sum_d += a - w;
    sum_d2 += (a - w) * (a - w);
    out.spread += a;
    out.predicted += w;
  }
  out.z = sum_d2 > 0.0 ? sum_d / std::sqrt(sum_d2) : 0.0;
  return out;
}

TEST(QmcEstimator, SplitVariancePredictsTheSpreadOverSeeds) {
  // With the blocker's penumbra. |z| <= 4: a false alarm has probability 6e-5 for a correct
  // estimator. An estimator that ignored the stratification (one computed from all samples as if
  // they were independent) would predict the independent sampler's variance, several times the
  // spread (the ratio printed by the next test), far beyond 4.
  set_thread_count(0);
  const Scene s = floor_under_square(true);
  for (PtSampler sampler : {PtSampler::Sobol, PtSampler::Independent}) {
    const Spread sp = spread_over_seeds(s, sampler, 12, 32);
    std::printf("[qmc %s] spread over 12 seeds / predicted = %.3f, z = %.2f\n", to_string(sampler).c_str(),
                sp.spread / sp.predicted, sp.z);
    EXPECT_LT(std::abs(sp.z), 4.0);
  }
}

TEST(QmcEstimator, SobolLowersTheVarianceOfTheMean) {
  // Measured 2026-12-03 (seeds fixed, deterministic): 0.022 open, 0.078 penumbra; the bounds leave
  // a factor > 2 for other seeds and scramble constants. The bound is a
  // property of the sampler, not of speed: at 64 spp (32 points per replicate) a stratified 2D
  // light sample of a smooth integrand must beat independent sampling by far.
  set_thread_count(0);
  for (bool blocker : {false, true}) {
    const Scene s = floor_under_square(blocker);
    double var[2] = {0.0, 0.0};
    int i = 0;
    for (PtSampler sampler : {PtSampler::Sobol, PtSampler::Independent}) {
      const Image v = render(s, sampler, 5u, 64).variance(kFull);
      for (float x : v.data) var[i] += double(x);
      ++i;
    }
    std::printf("[qmc] %s: variance of the mean sobol / independent = %.3f\n", blocker ? "penumbra" : "open",
                var[0] / var[1]);
    EXPECT_LT(var[0] / var[1], blocker ? 0.2 : 0.05);
  }
}

}  // namespace
}  // namespace vct::pt
