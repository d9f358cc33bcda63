// The noise-aware bias judgement: PT noise alone is "consistent", a 5% bias is caught.
#include <gtest/gtest.h>

#include <random>

#include "compare/bias.h"

namespace vct::cmp {
namespace {

// A "PT" image with per-pixel half-split variance estimates (1 dof each, as the path tracer's),
// and a VCT image = truth (+ bias).
struct Synthetic {
  std::map<std::string, Image> pt;
  StageSet vct;
};

Synthetic make(float bias, uint32_t seed) {
  const int w = 96, h = 96;
  const double sigma = 0.02;  // std of the PT mean
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  Image mean(w, h, 3), var(w, h, 3), vct(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double truth = 0.3 + 0.2 * double(x) / w;
      // Two half means, each with variance 2 sigma^2: their average has variance sigma^2.
      const double e = truth + std::sqrt(2.0) * sigma * n01(rng), o = truth + std::sqrt(2.0) * sigma * n01(rng);
      const double m = 0.5 * (e + o), v = (e - o) * (e - o) / 4.0;
      for (int c = 0; c < 3; ++c) {
        mean.at(x, y, c) = float(m);
        var.at(x, y, c) = float(v);
        vct.at(x, y, c) = float(truth * (1.0 + double(bias)));
      }
    }
  Synthetic s;
  s.pt["pt_full"] = mean;
  s.pt["pt_full_var"] = var;
  s.vct.images["image.final"] = vct;
  return s;
}

const BiasComponent& full(const std::vector<BiasComponent>& v) {
  for (const auto& b : v)
    if (b.component == "full") return b;
  throw std::runtime_error("no full");
}

TEST(Bias, NoiseAloneIsNotBias) {
  const Synthetic s = make(0.0f, 7);
  const auto r = measure_bias(s.vct, s.pt);
  const BiasComponent& b = full(r);
  ASSERT_TRUE(b.available && b.have_variance);
  EXPECT_FALSE(b.significant) << b.note;
  EXPECT_LT(b.fraction_beyond_k_sigma, 2 * b.expected_fraction + 0.003);
  EXPECT_LT(std::abs(b.mean_bias_z), 5.0);
}

TEST(Bias, FivePercentBiasIsCaught) {
  const Synthetic s = make(0.05f, 7);
  const std::vector<BiasComponent> components = measure_bias(s.vct, s.pt);  // outlives b
  const BiasComponent& b = full(components);
  EXPECT_TRUE(b.significant) << b.note;
  EXPECT_NEAR(b.metrics.relative_bias, 0.05, 0.005);
}

TEST(Bias, MissingAovIsReportedNotThrown) {
  Synthetic s = make(0.0f, 1);
  s.pt.erase("pt_full");
  const std::vector<BiasComponent> components = measure_bias(s.vct, s.pt);  // outlives b
  const BiasComponent& b = full(components);
  EXPECT_FALSE(b.available);
  EXPECT_NE(b.note.find("pt_full"), std::string::npos);
}

}  // namespace
}  // namespace vct::cmp
