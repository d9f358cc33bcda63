// The scrambled Sobol building block (pt/sobol_scramble.h) and the per-decision sampler on it
// (pt/path_sampler.h): the net property that makes the samples stratified, and the uniformity
// (over seeds) that keeps the estimator unbiased.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "chi2.h"
#include "pt/path_sampler.h"
#include "pt/rng.h"
#include "pt/sobol_scramble.h"

namespace vct::pt {
namespace {

/// True when the points (32-bit fractions) form a (0,m,2)-net in base 2: every dyadic box of
/// 2^a by 2^(m-a) cells holds exactly one point.
bool is_net(const std::vector<uint32_t>& xs, const std::vector<uint32_t>& ys, int m) {
  for (int a = 0; a <= m; ++a) {
    std::vector<int> count(size_t(1) << m, 0);
    for (size_t i = 0; i < xs.size(); ++i) {
      const uint32_t cx = a == 0 ? 0u : xs[i] >> (32 - a), cy = a == m ? 0u : ys[i] >> (32 - (m - a));
      ++count[(size_t(cx) << (m - a)) | cy];
    }
    for (int c : count)
      if (c != 1) return false;
  }
  return true;
}

TEST(SobolScramble, FirstTwoDimensionsFormNets) {
  // Sobol's dimension 1 in index order (not Gray-code order): direction numbers 1/2, 3/4, 5/8
  // (m = 1, 3, 5), so indices 0..5 give 0, 1/2, 3/4, 1/4 (= 1/2 XOR 3/4), 5/8, 1/8.
  EXPECT_EQ(sobol_dim1(0), 0u);
  EXPECT_EQ(sobol_dim1(1), 0x80000000u);
  EXPECT_EQ(sobol_dim1(2), 0xC0000000u);
  EXPECT_EQ(sobol_dim1(3), 0x40000000u);
  EXPECT_EQ(sobol_dim1(4), 0xA0000000u);
  EXPECT_EQ(sobol_dim1(5), 0x20000000u);
  for (int m = 0; m <= 12; ++m) {
    // The first block of 2^m points, and a later aligned block.
    for (uint32_t start : {0u, 7u << m}) {
      std::vector<uint32_t> xs, ys;
      for (uint32_t k = start; k < start + (1u << m); ++k) {
        xs.push_back(sobol_dim0(k));
        ys.push_back(sobol_dim1(k));
      }
      EXPECT_TRUE(is_net(xs, ys, m)) << "m " << m << " start " << start;
    }
  }
}

TEST(SobolScramble, ReversedTableIsDimensionOneReversed) {
  Pcg32 r(1u, 2u);
  for (int i = 0; i < 10000; ++i) {
    const uint32_t k = r.next_u32() >> (i % 32);
    EXPECT_EQ(sobol_dim1_reversed(reverse_bits(k)), reverse_bits(sobol_dim1(k))) << k;
  }
}

TEST(SobolScramble, ScrambledAndShuffledPrefixesStayNets) {
  // What stratifies a pixel's samples: the first 2^m points of a replicate, for any m, after the
  // index shuffle and the coordinate scrambles, are still one point per dyadic box.
  for (uint64_t trial = 0; trial < 8; ++trial) {
    const uint64_t s0 = mix64(trial), s1 = mix64(s0), s2 = mix64(s1);
    for (int m = 0; m <= 10; ++m) {
      std::vector<uint32_t> xs, ys;
      for (uint32_t k = 0; k < (1u << m); ++k) {
        const uint32_t j = shuffle_index(k, s0);
        xs.push_back(nested_scramble(sobol_dim0(j), s1));
        ys.push_back(nested_scramble(sobol_dim1(j), s2));
      }
      EXPECT_TRUE(is_net(xs, ys, m)) << "trial " << trial << " m " << m;
    }
  }
  // The shuffle is a permutation that keeps aligned blocks whole.
  std::vector<int> seen(1024, 0);
  for (uint32_t k = 0; k < 1024; ++k) ++seen[shuffle_index(k, 0x1234567890ABCDEFull) & 1023u];
  for (int c : seen) EXPECT_EQ(c, 1);
}

/// chi^2 p-value of counts against a uniform expectation.
double uniform_p_value(const std::vector<int>& count, int n) {
  const double e = double(n) / double(count.size());
  double chi2 = 0.0;
  for (int c : count) chi2 += (c - e) * (c - e) / e;
  return test::gamma_q(0.5 * double(count.size() - 1), 0.5 * chi2);
}

TEST(PathSampler, OneSampleIsUniformOverPixelsJointlyAcrossDecisions) {
  // Unbiasedness needs each sample's numbers jointly uniform over the randomisation (pixel and
  // seed hashes): for a fixed sample index, the emitter point and the BSDF direction of vertex 1
  // and the BSDF direction of vertex 2 over 40 000 pixels, in 2D projections across decisions
  // (8 x 8 cells, 63 dof). The seeds are fixed, so the test is deterministic; a p-value below
  // 1e-4 would be a dependence between decisions, not chance.
  constexpr int kPixels = 40000, kCells = 8;
  for (uint32_t sample : {0u, 1u, 6u, 37u}) {
    std::vector<int> emitter_vs_bsdf(kCells * kCells, 0), bsdf1_vs_bsdf2(kCells * kCells, 0),
        lobe_vs_emitter(kCells * kCells, 0);
    for (int p = 0; p < kPixels; ++p) {
      PathSampler s(PtSampler::Sobol, uint64_t(p), sample, 3u);
      const PathSampler::EmitterDraw e = s.emitter(1);
      float lobe1, lobe2;
      vec2 d1, d2;
      s.bsdf(1, true, lobe1, d1);
      s.bsdf(2, true, lobe2, d2);
      const auto cell = [](double u) { return std::min(int(u * kCells), kCells - 1); };
      ++emitter_vs_bsdf[size_t(cell(e.x) * kCells + cell(d1.y))];
      ++bsdf1_vs_bsdf2[size_t(cell(d1.x) * kCells + cell(d2.x))];
      ++lobe_vs_emitter[size_t(cell(lobe1) * kCells + cell(e.u.y))];
    }
    const double p1 = uniform_p_value(emitter_vs_bsdf, kPixels), p2 = uniform_p_value(bsdf1_vs_bsdf2, kPixels),
                 p3 = uniform_p_value(lobe_vs_emitter, kPixels);
    std::printf("[sampler uniformity] sample %u: p = %.3f %.3f %.3f\n", sample, p1, p2, p3);
    EXPECT_GT(p1, 1e-4);
    EXPECT_GT(p2, 1e-4);
    EXPECT_GT(p3, 1e-4);
  }
}

TEST(PathSampler, IndependentSamplerIsThePcgStreamInPathOrder) {
  // pt.sampler = independent draws exactly what the path tracer drew before the sobol sampler
  // existed: one PCG32 stream per (pixel, sample), consumed in path order.
  PathSampler s(PtSampler::Independent, 77u, 5u, 9u);
  Pcg32 r = sample_rng(77u, 5u, 9u);
  const PathSampler::EmitterDraw e = s.emitter(1);
  EXPECT_FALSE(e.reuse_x);
  EXPECT_EQ(e.u_select, r.next_float());
  EXPECT_EQ(e.u.x, r.next_float());
  EXPECT_EQ(e.u.y, r.next_float());
  EXPECT_EQ(s.particle(1), r.next_float());
  float lobe;
  vec2 u;
  s.bsdf(1, true, lobe, u);
  EXPECT_EQ(lobe, r.next_float());
  EXPECT_EQ(u.x, r.next_float());
  EXPECT_EQ(u.y, r.next_float());
  EXPECT_EQ(s.roulette(), r.next_float());
}

TEST(PathSampler, ReplicatesAreStratifiedPerPixel) {
  // A pixel's even samples are one scrambled sequence, its odd samples another: the first 2^m of
  // each replicate put one BSDF direction in each of 2^m columns (the x projection of a net).
  for (uint32_t half = 0; half < 2; ++half) {
    constexpr int m = 6;
    std::vector<int> count(1 << m, 0);
    for (uint32_t k = 0; k < (1u << m); ++k) {
      PathSampler s(PtSampler::Sobol, 1234u, 2 * k + half, 0u);
      float lobe;
      vec2 u;
      s.bsdf(1, true, lobe, u);
      ++count[size_t(u.x * (1 << m))];
    }
    for (int c : count) EXPECT_EQ(c, 1) << "replicate " << half;
  }
}

}  // namespace
}  // namespace vct::pt
