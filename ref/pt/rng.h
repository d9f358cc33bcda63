// Random numbers for the path tracer. Every (pixel, sample) pair gets its own PCG32 stream seeded
// from a hash of (pixel index, sample index, settings seed), so a pixel's samples never depend
// on which thread or tile computed them: the image is byte-identical for any thread count.
#pragma once

#include <cstdint>

#include "core/math.h"

namespace vct::pt {

/// SplitMix64 finaliser: a cheap 64-bit bijective mixer, used only for seeding.
inline uint64_t mix64(uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// PCG32 (O'Neill 2014, XSH-RR output), 64-bit state, selectable stream.
class Pcg32 {
 public:
  Pcg32(uint64_t seed, uint64_t stream) : inc_((stream << 1u) | 1u) {
    next_u32();
    state_ += seed;
    next_u32();
  }

  uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  /// Uniform in [0, 1): 24 random bits, exactly representable, never 1.
  float next_float() { return float(next_u32() >> 8u) * (1.0f / 16777216.0f); }
  vec2 next_2d() {
    const float a = next_float();
    return vec2(a, next_float());
  }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

/// The stream for one sample of one pixel.
inline Pcg32 sample_rng(uint64_t pixel_index, uint64_t sample_index, uint32_t seed) {
  const uint64_t key = mix64(mix64(pixel_index ^ (uint64_t(seed) << 40u)) ^ sample_index);
  return Pcg32(key, mix64(key ^ 0xDA3E39CB94B95BDBull));
}

}  // namespace vct::pt
