// The random numbers of one path sample, by decision (emitter point, BSDF direction, lobe, ...).
//
// Two samplers (pt.sampler):
// - independent: one PCG32 stream per (pixel, sample), consumed in path order (pt/rng.h);
// - sobol (default): randomised quasi-Monte Carlo for the decisions at the first kQmcDepth
//   vertices (path_sampler.cpp), PCG32 for the rest. A pixel's even samples are the points 0, 1, 2, ... of one
//   scrambled sequence and its odd samples those of a second, independently scrambled one
//   (replicate = sample & 1, point = sample >> 1). The two half-means the accumulator keeps
//   (pt/accumulator.h) are then two independent, identically distributed unbiased estimates, so
//   the sample-split variance stays an unbiased estimate of the pixel mean's variance (for an even
//   sample count) while each half is stratified (docs/pathtracer.md "Variance").
//   Each decision of each vertex (a 2D "pair") uses its own index shuffle and scrambles of Sobol's
//   first two dimensions (pt/sobol_scramble.h); every seed is a hash of (settings seed, pixel,
//   replicate, pair), so pixels and replicates are independent and a sample never depends on the
//   thread that computed it.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "core/settings.h"
#include "pt/rng.h"

namespace vct::pt {

class PathSampler {
 public:
  PathSampler(PtSampler kind, uint64_t pixel_index, uint32_t sample, uint32_t seed);

  /// The emitter decision at vertex `depth`: u_select picks the triangle, u the point on it.
  /// For the sobol sampler (reuse_x) `x` both selects the triangle and places the point along
  /// u.x (EmissiveTriangles::sample_reusing), so the whole 2D point set stays stratified over the
  /// lights' area; x carries 53 bits (the scrambled 32 and 21 independent ones) so that the part
  /// left after selecting a triangle of small probability keeps a float's 24 bits.
  struct EmitterDraw {
    bool reuse_x = false;
    double x = 0.0;
    float u_select = 0.0f;
    vec2 u{0.0f};
  };
  EmitterDraw emitter(int depth);
  float particle(int depth);
  /// u_lobe picks the BSDF lobe, u the direction. lobe_matters = false (a BSDF that samples one
  /// lobe only) lets the sobol sampler skip the lobe's pair; the independent one always draws it.
  void bsdf(int depth, bool lobe_matters, float& u_lobe, vec2& u);
  float roulette() { return rng_.next_float(); }

 private:
  /// Whether vertex `depth`'s decisions come from the scrambled sequence (path_sampler.cpp).
  bool qmc(int depth) const;
  /// Point index_ of the scrambled 2D sequence of pair `pair` of vertex `depth`, as 32-bit
  /// fractions; pair() as floats.
  void pair_bits(int depth, int pair, uint32_t& x, uint32_t& y) const;
  vec2 pair(int depth, int pair) const;

  PtSampler kind_;
  Pcg32 rng_;
  uint64_t replicate_key_ = 0;  // hash of (seed, pixel, sample & 1)
  uint32_t index_reversed_ = 0;  // sample >> 1, bits reversed
  // The lobe and particle decisions share one pair per vertex: computed once when first drawn.
  int cached_depth_ = 0;
  vec2 cached_pair_{0.0f};
  vec2 lobe_particle(int depth);
};

}  // namespace vct::pt
