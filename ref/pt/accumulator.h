// Per-pixel sums of the path samples, in double precision, kept as two independent halves (even
// and odd sample indices) so every AOV gets a per-pixel variance estimate of its mean.
// Samples are added pass by pass (one sample per pixel per pass, in sample order), so a pixel's
// sums are the same floating-point operations whatever the thread count or tiling.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "pt/integrator.h"

namespace vct::pt {

class Accumulator {
 public:
  static constexpr int kValuesPerPixel = 2 * kAovCount * 3;  // [half][aov][rgb]

  Accumulator() = default;
  Accumulator(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Completed passes = samples per pixel.
  uint32_t samples() const { return samples_; }
  void set_samples(uint32_t n) { samples_ = n; }

  void add(int x, int y, uint32_t sample, const PathSample& s);

  /// Mean of an AOV over all samples (zeros before the first pass).
  Image mean(Aov aov) const;
  /// Variance of that mean, per channel, from the two half-sample means:
  /// (m_even - m_odd)^2 * n_even * n_odd / n^2 (unbiased; zero while n < 2).
  Image variance(Aov aov) const;

  std::vector<double>& sums() { return sums_; }
  const std::vector<double>& sums() const { return sums_; }

 private:
  int width_ = 0, height_ = 0;
  uint32_t samples_ = 0;
  std::vector<double> sums_;
};

}  // namespace vct::pt
