#include "scene/texture_sample.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/srgb.h"
#include "scene/texture_lod.h"
#include "scene/texture_mips.h"

namespace vct {

float srgb8_to_linear(uint8_t v) {
  // A table lookup instead of a pow per channel, with identical bits.
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgb_to_linear(float(i) / 255.0f);
    return t;
  }();
  return table[v];
}

namespace {

/// §8.14.2 wrap modes on integer texel indices.
int wrap_index(int i, int size, Wrap mode) {
  if (i >= 0 && i < size) return i;  // every mode leaves texels inside the image alone
  switch (mode) {
    case Wrap::ClampToEdge:
      return std::clamp(i, 0, size - 1);
    case Wrap::MirroredRepeat: {
      const int period = 2 * size;
      int m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case Wrap::Repeat:
    default:
      return ((i % size) + size) % size;
  }
}

vec4 fetch(const uint8_t* texels, int width, int x, int y, bool srgb) {
  const uint8_t* px = &texels[(size_t(y) * size_t(width) + size_t(x)) * 4];
  if (srgb)
    return vec4(srgb8_to_linear(px[0]), srgb8_to_linear(px[1]), srgb8_to_linear(px[2]),
                px[3] / 255.0f);
  return vec4(px[0] / 255.0f, px[1] / 255.0f, px[2] / 255.0f, px[3] / 255.0f);
}

}  // namespace

vec4 sample_level(const Texture& tex, const uint8_t* texels, int width, int height, vec2 uv,
                  bool linear, bool srgb, vec2 texel_shift) {
  if (!linear) {
    // NEAREST: texel i covers [i, i+1) in texel units.
    const int x = wrap_index(int(std::floor(uv.x * float(width) + texel_shift.x)), width, tex.wrap_s);
    const int y =
        wrap_index(int(std::floor(uv.y * float(height) + texel_shift.y)), height, tex.wrap_t);
    return fetch(texels, width, x, y, srgb);
  }
  // LINEAR: the four texels around (u - 1/2, v - 1/2), weighted by the fractions.
  const float u = uv.x * float(width) - 0.5f + texel_shift.x,
              v = uv.y * float(height) - 0.5f + texel_shift.y;
  const float fu = std::floor(u), fv = std::floor(v);
  const float au = u - fu, av = v - fv;
  const int x0 = wrap_index(int(fu), width, tex.wrap_s),
            x1 = wrap_index(int(fu) + 1, width, tex.wrap_s);
  const int y0 = wrap_index(int(fv), height, tex.wrap_t),
            y1 = wrap_index(int(fv) + 1, height, tex.wrap_t);
  return (1.0f - av) * ((1.0f - au) * fetch(texels, width, x0, y0, srgb) +
                        au * fetch(texels, width, x1, y0, srgb)) +
         av * ((1.0f - au) * fetch(texels, width, x0, y1, srgb) +
               au * fetch(texels, width, x1, y1, srgb));
}

vec4 sample_texture_lod(const Texture& tex, vec2 uv, bool srgb, double lambda,
                        bool decode_after_filter, vec2 texel_shift) {
  if (tex.width <= 0 || tex.height <= 0) return vec4(1.0f);
  const LevelBlend b = select_levels(tex, lambda, available_levels(tex, srgb) - 1);
  // The chain is the one built for `srgb` reads either way; only where the decode happens moves.
  const bool decode_texels = srgb && !decode_after_filter;
  int w = 0, h = 0;
  const uint8_t* t1 = mip_level_texels(tex, srgb, b.level1, w, h);
  vec4 v = sample_level(tex, t1, w, h, uv, b.linear, decode_texels, texel_shift);
  if (b.weight2 != 0.0f && b.level2 != b.level1) {
    const uint8_t* t2 = mip_level_texels(tex, srgb, b.level2, w, h);
    const vec4 v2 = sample_level(tex, t2, w, h, uv, b.linear, decode_texels, texel_shift);
    v = (1.0f - b.weight2) * v + b.weight2 * v2;
  }
  if (srgb && decode_after_filter)
    v = vec4(srgb_to_linear(v.r), srgb_to_linear(v.g), srgb_to_linear(v.b), v.a);
  return v;
}

}  // namespace vct
