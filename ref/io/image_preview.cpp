// PNG previews (display transform, sRGB curve, 8 bits); the bytes go to write_bytes_png
// (io/png_bytes.h). Data stages (EXR, NRRD) never pass through here: they stay linear.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/image_io.h"
#include "io/png_bytes.h"

namespace vct {

namespace {

// Khronos PBR Neutral (Khronos 3D Commerce, 2024; docs/report.md, "Display transform"): colours
// below 0.76 pass unchanged except a small toe that removes a near-black offset (at most 0.04);
// above, the largest channel is compressed toward 1 along 1 - d^2 / (p + d - 0.76), d = 0.24, and
// the colour desaturates toward white by 1 - 1 / (0.15 (p - p') + 1). Hue is kept: base colours
// under moderate light display as authored, which is why the glTF Sample Viewer defaults to it.
glm::vec3 khronos_pbr_neutral(glm::vec3 c) {
  constexpr float kStartCompression = 0.8f - 0.04f, kDesaturation = 0.15f;
  const float lowest = std::min(c.r, std::min(c.g, c.b));
  const float offset = lowest < 0.08f ? lowest - 6.25f * lowest * lowest : 0.04f;
  c -= offset;
  const float peak = std::max(c.r, std::max(c.g, c.b));
  if (peak < kStartCompression) return c;
  constexpr float d = 1.0f - kStartCompression;
  const float new_peak = 1.0f - d * d / (peak + d - kStartCompression);
  c *= new_peak / peak;
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
  return glm::mix(c, glm::vec3(new_peak), g);
}

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
    case ToneMap::KhronosPbrNeutral:
      return khronos_pbr_neutral(glm::vec3(v)).r;
  }
  return v;
}

// One pixel's displayed colour (before the sRGB curve): PBR Neutral works on the colour as a
// whole, the others per channel. Non-finite values display as 0.
glm::vec3 display_rgb(glm::vec3 c, ToneMap tm) {
  for (int i = 0; i < 3; ++i) c[i] = std::isfinite(c[i]) ? std::max(c[i], 0.0f) : 0.0f;
  if (tm == ToneMap::KhronosPbrNeutral) return glm::clamp(khronos_pbr_neutral(c), 0.0f, 1.0f);
  return {tone_map(c.r, tm), tone_map(c.g, tm), tone_map(c.b, tm)};
}

// lround's bytes without its library call (a tenth of the stage-set writes' time, docs/performance.md,
// "Where validate's time goes"): for s in [0, 255] a float, s + 0.5 is exact in double, and its
// floor rounds halves up as lround does for non-negative values.
uint8_t to_byte(float unit) {
  const float s = std::clamp(unit, 0.0f, 1.0f) * 255.0f;
  return uint8_t(int(double(s) + 0.5));
}

}  // namespace

const char* tone_map_name(ToneMap tm) {
  switch (tm) {
    case ToneMap::Clamp: return "clamp";
    case ToneMap::Reinhard: return "Reinhard";
    case ToneMap::Aces: return "ACES (Narkowicz fit)";
    case ToneMap::KhronosPbrNeutral: return "Khronos PBR Neutral";
  }
  return "?";
}

void write_png(const std::string& path, const Image& img, float exposure, ToneMap tm) {
  const int out_c = img.channels >= 3 ? 3 : 1;
  std::vector<uint8_t> bytes(size_t(img.width) * size_t(img.height) * size_t(out_c));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const glm::vec3 linear = out_c == 3 ? img.rgb(x, y) : glm::vec3(img.at(x, y, 0));
      const glm::vec3 shown = display_rgb(linear * exposure, tm);
      for (int c = 0; c < out_c; ++c)
        bytes[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(out_c) + size_t(c)] = to_byte(linear_to_srgb(shown[c]));
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
