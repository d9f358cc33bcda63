// Sampling tests for the BRDF mixture (Nori's habit: every warp is checked against its pdf).
//  * chi^2 goodness of fit of sample_bsdf against bsdf_pdf integrated over (theta, phi) bins,
//    for several roughness / view angle / material combinations;
//  * the fraction of valid samples equals the pdf's integral over the hemisphere;
//  * energy conservation of the pipelines' Cook–Torrance: the albedo integral of f cos <= 1;
//  * two estimators of that integral (mixture sampling vs cosine sampling) agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pt/bsdf_sampling.h"
#include "pt/rng.h"
#include "shared/vct_shared.h"
#include "chi2.h"

namespace vct::pt {
namespace {

TEST(Chi2, GammaQMatchesKnownValues) {
  // chi^2 with 10 dof: P(X > 18.307) = 0.05; with 1 dof: P(X > 3.841) = 0.05.
  EXPECT_NEAR(test::gamma_q(5.0, 18.307 / 2.0), 0.05, 1e-4);
  EXPECT_NEAR(test::gamma_q(0.5, 3.841 / 2.0), 0.05, 1e-4);
}

BsdfPoint make_point(const vec3& albedo, float metallic, float roughness, float theta_v_deg) {
  const float t = glm::radians(theta_v_deg);
  const vec3 n(0, 0, 1), v(std::sin(t), 0.0f, std::cos(t));
  return make_bsdf_point(sh::surface_pbr(albedo, metallic, roughness, 1.0f, vec3(1.0f)), n, n, v);
}

struct Case {
  float roughness, theta_v, metallic;
};

class BsdfChi2 : public ::testing::TestWithParam<Case> {};

TEST_P(BsdfChi2, SamplesFollowPdf) {
  const Case c = GetParam();
  const BsdfPoint bp = make_point(vec3(0.6f, 0.5f, 0.4f), c.metallic, c.roughness, c.theta_v);
  constexpr int kTheta = 12, kPhi = 24, kSub = 24;
  constexpr int kSamples = 400000;
  // Expected mass per bin: midpoint rule on a kSub x kSub grid, Jacobian sin(theta).
  std::vector<double> expected(kTheta * kPhi, 0.0);
  const double dt = 0.5 * double(kPi) / kTheta, dp = 2.0 * double(kPi) / kPhi;
  double total_mass = 0.0;
  for (int i = 0; i < kTheta; ++i)
    for (int j = 0; j < kPhi; ++j) {
      double m = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          const double th = (i + (a + 0.5) / kSub) * dt, ph = (j + (b + 0.5) / kSub) * dp;
          const vec3 l(float(std::sin(th) * std::cos(ph)), float(std::sin(th) * std::sin(ph)), float(std::cos(th)));
          m += double(bsdf_pdf(bp, l)) * std::sin(th);
        }
      expected[size_t(i * kPhi + j)] = m * (dt / kSub) * (dp / kSub);
      total_mass += expected[size_t(i * kPhi + j)];
    }
  std::vector<double> observed(expected.size(), 0.0);
  Pcg32 rng(12345u + uint64_t(c.roughness * 1000) + uint64_t(c.theta_v), 99u);
  int valid = 0;
  for (int s = 0; s < kSamples; ++s) {
    const float u_lobe = rng.next_float();
    const BsdfSample bs = sample_bsdf(bp, u_lobe, rng.next_2d());
    if (!bs.valid) continue;
    ++valid;
    // The returned pdf must be the pdf function's value.
    ASSERT_NEAR(bs.pdf, bsdf_pdf(bp, bs.l), 1e-4f * bs.pdf);
    const double th = std::acos(std::clamp(double(bs.l.z), 0.0, 1.0));
    double ph = std::atan2(double(bs.l.y), double(bs.l.x));
    if (ph < 0.0) ph += 2.0 * double(kPi);
    const int i = std::min(kTheta - 1, int(th / dt)), j = std::min(kPhi - 1, int(ph / dp));
    observed[size_t(i * kPhi + j)] += 1.0;
  }
  // Valid fraction == integral of the pdf over the hemisphere (binomial 4 sigma + quadrature).
  const double frac = double(valid) / kSamples;
  EXPECT_NEAR(frac, total_mass, 4.0 * std::sqrt(total_mass * (1 - total_mass) / kSamples) + 2e-3);
  // chi^2 of the valid samples against the normalised pdf, pooling bins expecting < 5.
  double chi2 = 0.0, pool_e = 0.0, pool_o = 0.0;
  int dof = -1;
  for (size_t k = 0; k < expected.size(); ++k) {
    const double e = expected[k] / total_mass * valid;
    if (e < 5.0) {
      pool_e += e;
      pool_o += observed[k];
      continue;
    }
    chi2 += (observed[k] - e) * (observed[k] - e) / e;
    ++dof;
  }
  if (pool_e > 0.0) {
    chi2 += (pool_o - pool_e) * (pool_o - pool_e) / std::max(pool_e, 5.0);
    ++dof;
  }
  const double p = test::gamma_q(0.5 * dof, 0.5 * chi2);
  std::printf("[chi2 roughness=%.2f theta_v=%.0f metallic=%.1f] chi2=%.1f dof=%d p=%.4f valid=%.4f\n",
              double(c.roughness), double(c.theta_v), double(c.metallic), chi2, dof, p, frac);
  // 12 cases at an overall significance of 1 %: Sidak-corrected per-case level ~ 8.4e-4.
  EXPECT_GT(p, 8.4e-4);
}

INSTANTIATE_TEST_SUITE_P(Combos, BsdfChi2,
                         ::testing::Values(Case{0.25f, 15.0f, 0.0f}, Case{0.25f, 50.0f, 0.0f}, Case{0.25f, 80.0f, 0.0f},
                                           Case{0.5f, 15.0f, 0.0f}, Case{0.5f, 50.0f, 1.0f}, Case{0.5f, 80.0f, 0.0f},
                                           Case{1.0f, 15.0f, 0.0f}, Case{1.0f, 50.0f, 1.0f}, Case{1.0f, 80.0f, 1.0f},
                                           Case{0.35f, 30.0f, 1.0f}, Case{0.35f, 70.0f, 1.0f},
                                           Case{0.7f, 60.0f, 0.5f}));

/// Albedo integral of cook_torrance * cos by importance sampling: mean and standard error.
struct Estimate {
  vec3 mean{0.0f}, sigma{0.0f};
};

Estimate albedo_integral(const BsdfPoint& bp, bool mixture, int n, uint64_t seed) {
  Pcg32 rng(seed, 5u);
  const sh::Frame f = sh::frame_from_normal(bp.n);
  std::array<double, 3> s{}, s2{};
  for (int i = 0; i < n; ++i) {
    vec3 w(0.0f);
    const float u_lobe = rng.next_float();
    const vec2 u = rng.next_2d();
    if (mixture) {
      const BsdfSample bs = sample_bsdf(bp, u_lobe, u);
      if (bs.valid) w = eval_bsdf(bp, bs.l).total() * glm::dot(bp.n, bs.l) / bs.pdf;
    } else {
      const vec3 l = sh::frame_to_world(f, sample_cosine_hemisphere(u));
      const float pdf = cosine_hemisphere_pdf(sample_cosine_hemisphere(u));
      if (pdf > 0.0f) w = eval_bsdf(bp, l).total() * glm::dot(bp.n, l) / pdf;
    }
    for (int c = 0; c < 3; ++c) {
      s[size_t(c)] += double(w[c]);
      s2[size_t(c)] += double(w[c]) * double(w[c]);
    }
  }
  Estimate e;
  for (int c = 0; c < 3; ++c) {
    const double m = s[size_t(c)] / n, var = std::max(0.0, s2[size_t(c)] / n - m * m);
    e.mean[c] = float(m);
    e.sigma[c] = float(std::sqrt(var / n));
  }
  return e;
}

TEST(BsdfEnergy, WhiteFurnaceIntegralAtMostOne) {
  // Metals at every angle and dielectrics up to 45 degrees reflect at most what they receive.
  float worst = 0.0f;
  for (float metallic : {0.0f, 1.0f})
    for (float r : {0.03f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f})
      for (float th : {0.0f, 30.0f, 45.0f, 60.0f, 80.0f, 88.0f}) {
        if (metallic == 0.0f && th > 45.0f) continue;  // see the next test
        const BsdfPoint bp = make_point(vec3(1.0f), metallic, r, th);
        const Estimate e = albedo_integral(bp, true, 100000, 77u);
        for (int c = 0; c < 3; ++c)
          EXPECT_LE(e.mean[c], 1.0f + 4.0f * e.sigma[c])
              << "metallic " << metallic << " roughness " << r << " theta_v " << th << " sigma " << e.sigma[c];
        worst = std::max(worst, e.mean.g);
        if (th == 0.0f || th == 88.0f)
          std::printf("[energy metallic=%.0f roughness=%.2f theta_v=%.0f] integral=%.4f +- %.4f\n", double(metallic),
                      double(r), double(th), double(e.mean.g), double(e.sigma.g));
      }
  std::printf("[energy] largest albedo integral (conserving cases) %.4f\n", double(worst));
}

TEST(BsdfEnergy, SmoothDielectricGainsEnergyAtGrazingView) {
  // A property of the seed's BRDF, not of the sampler: kd = (1 - F(h.v)) ignores the energy the
  // specular lobe takes at grazing view, so a white, smooth dielectric reflects up to ~10 % more
  // than it receives there (the VCT pipelines share the BRDF, so comparisons stay fair; the
  // path tracer just reproduces it). Pinned here so a change of the shared BRDF is noticed.
  for (float r : {0.03f, 0.1f, 0.25f}) {
    const Estimate e60 = albedo_integral(make_point(vec3(1.0f), 0.0f, r, 60.0f), true, 100000, 77u);
    const Estimate e80 = albedo_integral(make_point(vec3(1.0f), 0.0f, r, 80.0f), true, 100000, 77u);
    std::printf("[energy dielectric roughness=%.2f] theta_v=60: %.4f +- %.4f, theta_v=80: %.4f +- %.4f\n", double(r),
                double(e60.mean.g), double(e60.sigma.g), double(e80.mean.g), double(e80.sigma.g));
    EXPECT_GT(e80.mean.g, 1.0f + 4.0f * e80.sigma.g);
    EXPECT_LT(e80.mean.g, 1.12f);
    EXPECT_LT(e60.mean.g, 1.02f);
  }
  // The excess is confirmed by an estimator that does not use the mixture sampler at all.
  const BsdfPoint bp = make_point(vec3(1.0f), 0.0f, 0.25f, 80.0f);
  const Estimate a = albedo_integral(bp, true, 200000, 8u), b = albedo_integral(bp, false, 400000, 9u);
  EXPECT_NEAR(a.mean.g, b.mean.g, 4.0f * std::sqrt(a.sigma.g * a.sigma.g + b.sigma.g * b.sigma.g));
  EXPECT_GT(b.mean.g, 1.0f + 4.0f * b.sigma.g);
}

TEST(BsdfEnergy, MixtureAndCosineEstimatorsAgree) {
  // Importance sampling with the mixture must estimate the same integral as plain cosine
  // sampling: checks the mixture weights f cos / pdf, not just the shape of the samples.
  for (float r : {0.4f, 0.7f, 1.0f})
    for (float th : {20.0f, 70.0f}) {
      const BsdfPoint bp = make_point(vec3(0.8f, 0.5f, 0.2f), 0.3f, r, th);
      const Estimate a = albedo_integral(bp, true, 200000, 3u), b = albedo_integral(bp, false, 200000, 4u);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a.mean[c], b.mean[c], 4.0f * std::sqrt(a.sigma[c] * a.sigma[c] + b.sigma[c] * b.sigma[c]))
            << "roughness " << r << " theta_v " << th;
    }
}

}  // namespace
}  // namespace vct::pt

namespace vct::pt {
namespace {

/// Albedo at v = n of a metal (f0 = albedo, f90 = 1), written out in double precision from the
/// seed's formulas (GGX D with alpha = r^2, Schlick F, Schlick-GGX G with k = (r+1)^2/8): an
/// independent reference. At v = n the integrand depends on theta_l only (1D midpoint rule).
double metal_albedo_double(double f0, double r) {
  const double a2 = r * r * r * r, k = (r + 1) * (r + 1) / 8.0;
  constexpr int kSteps = 400000;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double tl = (i + 0.5) / kSteps * 0.5 * double(kPi), th = 0.5 * tl;  // h halfway to n
    const double cl = std::cos(tl), ch = std::cos(th), sh2 = std::sin(th) * std::sin(th);
    const double d = a2 / (double(kPi) * std::pow(ch * ch * a2 + sh2, 2.0));  // no cancellation
    const double f = f0 + (1 - f0) * std::pow(1 - ch, 5.0);
    const double g = cl / (cl * (1 - k) + k);  // G1(v = n) = 1
    sum += f * d * g / (4 * cl) * cl * std::sin(tl) * 2 * double(kPi) * (0.5 * double(kPi) / kSteps);
  }
  return sum;
}

TEST(BsdfEnergy, LowRoughnessMixtureMatchesDoubleReference) {
  // Checks the VNDF pdf where the chi^2 bins are too coarse (sharp lobes): the estimator's weight
  // F G / G1 does not contain D, so it must reproduce the exact (double) integral.
  for (float r : {0.03f, 0.05f, 0.1f, 0.2f, 0.4f}) {
    const BsdfPoint bp = make_point(vec3(0.9f), 1.0f, r, 0.0f);
    const double ref = metal_albedo_double(0.9, double(r));
    const Estimate e = albedo_integral(bp, true, 200000, 21u);
    // For the record: the same integral of the float cook_torrance (its D loses precision near
    // n.h = 1 at low roughness: 1 - n.h^2 cancels in float).
    double quad = 0.0;
    constexpr int kSteps = 400000;
    for (int i = 0; i < kSteps; ++i) {
      const double th = (i + 0.5) / kSteps * 0.5 * double(kPi);
      const vec3 l(float(std::sin(th)), 0.0f, float(std::cos(th)));
      quad += double(eval_bsdf(bp, l).total().g) * std::cos(th) * std::sin(th) * 2.0 * double(kPi) *
              (0.5 * double(kPi) / kSteps);
    }
    std::printf("[low roughness %.2f] mixture %.5f +- %.5f, double reference %.5f, float-BRDF quadrature %.5f\n",
                double(r), double(e.mean.g), double(e.sigma.g), ref, quad);
    EXPECT_NEAR(double(e.mean.g), ref, 4.0 * double(e.sigma.g) + 2e-5);
  }
}

}  // namespace
}  // namespace vct::pt
