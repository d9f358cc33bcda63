#include "pt/accumulator.h"

namespace vct::pt {

Accumulator::Accumulator(int width, int height)
    : width_(width), height_(height), sums_(size_t(width) * size_t(height) * kValuesPerPixel, 0.0) {}

void Accumulator::add(int x, int y, uint32_t sample, const PathSample& s) {
  double* px = &sums_[(size_t(y) * size_t(width_) + size_t(x)) * kValuesPerPixel];
  double* half = px + (sample & 1u) * (kAovCount * 3);
  for (int a = 0; a < kAovCount; ++a) {
    // Most AOVs of a sample are 0 past its first vertex. Skipping them keeps the bits: a sum
    // starts at +0 and round-to-nearest never makes it -0, so adding +-0 would leave it as is.
    if (s.aov[a] == vec3(0.0f)) continue;
    for (int c = 0; c < 3; ++c) half[a * 3 + c] += double(s.aov[a][c]);
  }
}

Image Accumulator::mean(Aov aov) const {
  Image img(width_, height_, 3);
  img.channel_names = {"R", "G", "B"};
  if (samples_ == 0) return img;
  const double inv = 1.0 / double(samples_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const double* px = &sums_[(size_t(y) * size_t(width_) + size_t(x)) * kValuesPerPixel];
      for (int c = 0; c < 3; ++c)
        img.at(x, y, c) = float((px[aov * 3 + c] + px[kAovCount * 3 + aov * 3 + c]) * inv);
    }
  return img;
}

Image Accumulator::variance(Aov aov) const {
  Image img(width_, height_, 3);
  img.channel_names = {"R", "G", "B"};
  const double n = samples_, n_even = (samples_ + 1) / 2, n_odd = samples_ / 2;
  if (n_odd < 1) return img;
  const double scale = n_even * n_odd / (n * n);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const double* px = &sums_[(size_t(y) * size_t(width_) + size_t(x)) * kValuesPerPixel];
      for (int c = 0; c < 3; ++c) {
        const double d = px[aov * 3 + c] / n_even - px[kAovCount * 3 + aov * 3 + c] / n_odd;
        img.at(x, y, c) = float(d * d * scale);
      }
    }
  return img;
}

}  // namespace vct::pt
