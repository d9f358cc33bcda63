// The first two dimensions of Sobol's sequence, randomised by nested (Owen-type) scrambling: the
// building block of the path tracer's low-discrepancy samples (pt/path_sampler.h,
// docs/pathtracer.md "Random numbers and determinism").
//
// Why these two and no more: the first 2^m points of Sobol's dimensions 0 and 1 form a
// (0,m,2)-net in base 2 (every dyadic box of area 2^-m holds exactly one point), for every m.
// A path needs more dimensions than two, but each of its decisions is at most two-dimensional
// (an emitter point, a BSDF direction), so the sampler gives every decision its own independently
// scrambled and shuffled copy of this 2D sequence ("padding", Kollig & Keller 2002; Burley 2020,
// "Practical Hash-based Owen Scrambling"). That needs only dimension 1's direction numbers, which
// follow from its primitive polynomial x + 1 with m_1 = 1: m_k = 2 m_{k-1} XOR m_{k-1}, i.e. in
// 32-bit fixed point V_1 = 2^31 and V_k = V_{k-1} XOR (V_{k-1} >> 1) (Pascal's triangle mod 2).
// Dimension 0 is the van der Corput sequence, the index's bits reversed.
//
// The scramble (nested_scramble) works on the bits in reversed order, where a nested scramble may
// flip bit j only as a function of bits below j (the more significant digits of the fraction):
// adding a constant (carries travel up), multiplying by an odd constant, and x ^= x * even all do
// that and are bijections. So a scrambled net is again a net, and with a uniformly random 32-bit
// seed added first each scrambled point is exactly uniform on the 2^32 grid: estimates stay
// unbiased whatever the fixed mixing constants after the addition are (their only job is to make
// the flips depend on the prefix, which a plain XOR shift would not).
#pragma once

#include <array>
#include <cstdint>

namespace vct::pt {

constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

namespace detail {
/// Sobol dimension 1's direction numbers V_1..V_32 (primitive polynomial x + 1: V_k = V_{k-1} ^
/// (V_{k-1} >> 1), V_1 = 1/2), generated from the recurrence.
constexpr std::array<uint32_t, 32> sobol_dim1_directions() {
  std::array<uint32_t, 32> dir{};
  dir[0] = 0x80000000u;
  for (size_t k = 1; k < 32; ++k) dir[k] = dir[k - 1] ^ (dir[k - 1] >> 1);
  return dir;
}

/// Sobol dimension 1 by bytes of the index: table[b][v] = XOR of V_{8b+k+1} over the set bits k
/// of v, so a 32-bit index costs four lookups instead of a loop over its bits.
struct SobolDim1Table {
  std::array<std::array<uint32_t, 256>, 4> t{};
  constexpr SobolDim1Table() {
    const std::array<uint32_t, 32> dir = sobol_dim1_directions();
    for (int b = 0; b < 4; ++b)
      for (uint32_t v = 0; v < 256; ++v) {
        uint32_t x = 0;
        for (int k = 0; k < 8; ++k)
          if (v & (1u << k)) x ^= dir[8 * b + k];
        t[size_t(b)][v] = x;
      }
  }
};
inline constexpr SobolDim1Table kSobolDim1{};

/// The same map in reversed digit order: table[b][v] = reverse(dimension 1 of the index whose
/// reversed bits 8b..8b+7 are v), so a sampler that already holds the reversed index (the index
/// shuffle's output) needs no reversal before the lookup.
struct SobolDim1ReversedTable {
  std::array<std::array<uint32_t, 256>, 4> t{};
  constexpr SobolDim1ReversedTable() {
    const std::array<uint32_t, 32> dir = sobol_dim1_directions();
    for (int b = 0; b < 4; ++b)
      for (uint32_t v = 0; v < 256; ++v) {
        uint32_t x = 0;
        for (int k = 0; k < 8; ++k)
          if (v & (1u << k)) x ^= reverse_bits(dir[31 - (8 * b + k)]);
        t[size_t(b)][v] = x;
      }
  }
};
inline constexpr SobolDim1ReversedTable kSobolDim1Reversed{};
}  // namespace detail

/// Sobol point `index`, dimension 0 (van der Corput), as a 32-bit binary fraction.
inline uint32_t sobol_dim0(uint32_t index) { return reverse_bits(index); }

/// Sobol point `index`, dimension 1, as a 32-bit binary fraction.
inline uint32_t sobol_dim1(uint32_t index) {
  const auto& t = detail::kSobolDim1.t;
  return t[0][index & 0xFFu] ^ t[1][(index >> 8) & 0xFFu] ^ t[2][(index >> 16) & 0xFFu] ^ t[3][index >> 24];
}

/// reverse_bits(sobol_dim1(reverse_bits(r))).
inline uint32_t sobol_dim1_reversed(uint32_t r) {
  const auto& t = detail::kSobolDim1Reversed.t;
  return t[0][r & 0xFFu] ^ t[1][(r >> 8) & 0xFFu] ^ t[2][(r >> 16) & 0xFFu] ^ t[3][r >> 24];
}

/// A nested bijection of 32 bits in reversed digit order (bit 0 = the fraction's 1/2 digit; see
/// the file comment). seed_lo is added first (uniform seed -> uniform output); seed_hi is added
/// after a first mixing round, so that two scrambles differ by more than a shift.
inline uint32_t nested_scramble_reversed(uint32_t r, uint32_t seed_lo, uint32_t seed_hi) {
  r += seed_lo;
  r ^= r * 0x2C1B3C6Cu;  // even constants: bit j of the product depends on bits below j only
  r *= 0x9E3779B1u;      // odd (2^32 / golden ratio, rounded to odd)
  r += seed_hi;
  r ^= r * 0x5851F42Cu;
  r *= 0x85EBCA77u;
  r ^= r * 0x1B873594u;
  return r;
}

/// Nested scramble of a binary fraction x (bit 31 = the 1/2 digit).
inline uint32_t nested_scramble(uint32_t x, uint64_t seed) {
  return reverse_bits(nested_scramble_reversed(reverse_bits(x), uint32_t(seed), uint32_t(seed >> 32)));
}

/// A permutation of sample indices that maps every aligned block of 2^m indices onto an aligned
/// block of 2^m indices (bit j flips as a function of the bits above j): the first 2^m shuffled
/// points are still a whole (0,m,2)-net, but two decisions of one path no longer use the same
/// Sobol point (which would correlate them).
inline uint32_t shuffle_index(uint32_t index, uint64_t seed) {
  return reverse_bits(nested_scramble_reversed(reverse_bits(index), uint32_t(seed), uint32_t(seed >> 32)));
}

/// 24-bit float in [0, 1) from a 32-bit fraction (the same resolution as Pcg32::next_float).
inline float fraction_to_float(uint32_t x) { return float(x >> 8u) * (1.0f / 16777216.0f); }

}  // namespace vct::pt
