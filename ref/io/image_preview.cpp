// PNG previews (tone map, sRGB curve, 8 bits); the bytes go to write_bytes_png (io/png_bytes.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/image_io.h"
#include "io/png_bytes.h"

namespace vct {

namespace {

float tone_map(float v, ToneMap tm) {
  v = std::max(v, 0.0f);
  switch (tm) {
    case ToneMap::Clamp:
      return std::min(v, 1.0f);
    case ToneMap::Reinhard:
      return v / (1.0f + v);
    case ToneMap::Aces: {
      // Narkowicz's fit of the ACES filmic curve.
      const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
      return std::clamp((v * (a * v + b)) / (v * (c * v + d) + e), 0.0f, 1.0f);
    }
  }
  return v;
}

// lround's bytes without its library call (a tenth of the stage-set writes' time, docs/performance.md,
// "Where validate's time goes"): for s in [0, 255] a float, s + 0.5 is exact in double, and its
// floor rounds halves up as lround does for non-negative values.
uint8_t to_byte(float unit) {
  const float s = std::clamp(unit, 0.0f, 1.0f) * 255.0f;
  return uint8_t(int(double(s) + 0.5));
}

}  // namespace

void write_png(const std::string& path, const Image& img, float exposure, ToneMap tm) {
  const int out_c = img.channels >= 3 ? 3 : 1;
  std::vector<uint8_t> bytes(size_t(img.width) * size_t(img.height) * size_t(out_c));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < out_c; ++c) {
        float v = img.at(x, y, c) * exposure;
        if (!std::isfinite(v)) v = 0.0f;
        bytes[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(out_c) + size_t(c)] =
            to_byte(linear_to_srgb(tone_map(v, tm)));
      }
  write_bytes_png(path, img.width, img.height, out_c, bytes);
}

void write_png_linear(const std::string& path, const Image& img, float lo, float hi) {
  const int out_c = img.channels >= 3 ? 3 : 1;
  const float scale = hi > lo ? 1.0f / (hi - lo) : 1.0f;
  std::vector<uint8_t> bytes(size_t(img.width) * size_t(img.height) * size_t(out_c));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < out_c; ++c) {
        const float v = img.at(x, y, c);
        bytes[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(out_c) + size_t(c)] =
            to_byte(std::isfinite(v) ? (v - lo) * scale : 0.0f);
      }
  write_bytes_png(path, img.width, img.height, out_c, bytes);
}

}  // namespace vct
