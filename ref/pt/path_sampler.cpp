#include "pt/path_sampler.h"

#include "pt/sobol_scramble.h"

namespace vct::pt {

namespace {
// The decisions of one vertex that the scrambled sequence serves, one 2D pair each.
constexpr int kPairEmitter = 0, kPairBsdf = 1, kPairLobeParticle = 2, kPairsPerVertex = 3;

// Vertices 1..kQmcDepth draw their decisions from the scrambled sequence; deeper vertices and
// Russian roulette use the PCG32 stream.
constexpr int kQmcDepth = 3;

uint64_t replicate_key(uint64_t pixel_index, uint32_t sample, uint32_t seed) {
  // A tag apart from sample_rng's keys (mix64(... ^ sample)), so no pair seed is a PCG seed.
  return mix64(mix64(pixel_index ^ (uint64_t(seed) << 40u)) + 0x51ED270B2A9D7F3Bull * (2u + (sample & 1u)));
}
}  // namespace

PathSampler::PathSampler(PtSampler kind, uint64_t pixel_index, uint32_t sample, uint32_t seed)
    : kind_(kind),
      rng_(sample_rng(pixel_index, sample, seed)),
      replicate_key_(kind == PtSampler::Sobol ? replicate_key(pixel_index, sample, seed) : 0),
      index_reversed_(reverse_bits(sample >> 1u)) {}

bool PathSampler::qmc(int depth) const { return kind_ == PtSampler::Sobol && depth <= kQmcDepth; }

void PathSampler::pair_bits(int depth, int pair, uint32_t& x, uint32_t& y) const {
  const uint64_t h = mix64(replicate_key_ ^ (uint64_t(depth * kPairsPerVertex + pair) * 0x9E3779B97F4A7C15ull));
  // The shuffled index k = shuffle_index(index_, h), kept reversed (r = reverse(k)): dimension 0
  // is r itself and dimension 1 is looked up from r, so each coordinate is scrambled with one
  // reversal back to a fraction (pt/sobol_scramble.h; three reversals per pair instead of five).
  const uint32_t r = nested_scramble_reversed(index_reversed_, uint32_t(h), uint32_t(h >> 32u));
  const uint64_t sx = mix64(h ^ 0x2545F4914F6CDD1Dull), sy = mix64(h ^ 0x8C0B2C4B9A5D3E71ull);
  x = reverse_bits(nested_scramble_reversed(reverse_bits(r), uint32_t(sx), uint32_t(sx >> 32u)));
  y = reverse_bits(nested_scramble_reversed(sobol_dim1_reversed(r), uint32_t(sy), uint32_t(sy >> 32u)));
}

vec2 PathSampler::pair(int depth, int pair) const {
  uint32_t x, y;
  pair_bits(depth, pair, x, y);
  return vec2(fraction_to_float(x), fraction_to_float(y));
}

PathSampler::EmitterDraw PathSampler::emitter(int depth) {
  EmitterDraw d;
  if (!qmc(depth)) {
    d.u_select = rng_.next_float();
    d.u = rng_.next_2d();
    return d;
  }
  uint32_t x, y;
  pair_bits(depth, kPairEmitter, x, y);
  d.reuse_x = true;
  d.x = (double(x) + double(rng_.next_u32() >> 11u) * 0x1p-21) * 0x1p-32;
  d.u = vec2(0.0f, fraction_to_float(y));
  return d;
}

float PathSampler::particle(int depth) {
  if (!qmc(depth)) return rng_.next_float();
  return lobe_particle(depth).y;
}

void PathSampler::bsdf(int depth, bool lobe_matters, float& u_lobe, vec2& u) {
  if (!qmc(depth)) {
    u_lobe = rng_.next_float();
    u = rng_.next_2d();
    return;
  }
  // A one-lobe BSDF (probability 0 or 1) ignores u_lobe: its pair is not computed then.
  u_lobe = lobe_matters ? lobe_particle(depth).x : 0.0f;
  u = pair(depth, kPairBsdf);
}

vec2 PathSampler::lobe_particle(int depth) {
  if (cached_depth_ != depth) {
    cached_pair_ = pair(depth, kPairLobeParticle);
    cached_depth_ = depth;
  }
  return cached_pair_;
}

}  // namespace vct::pt
