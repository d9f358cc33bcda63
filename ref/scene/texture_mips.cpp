#include "scene/texture_mips.h"

#include <algorithm>
#include <cmath>

#include "io/srgb.h"
#include "scene/texture_sample.h"

namespace vct {

int mip_level_count(int width, int height) {
  int levels = 1;
  for (int s = std::max(width, height); s > 1; s /= 2) ++levels;
  return levels;
}

namespace {

uint8_t srgb_mean(const uint8_t v[4]) {
  // Summed in a fixed order: the same bits on every machine and thread count.
  const float linear = ((srgb8_to_linear(v[0]) + srgb8_to_linear(v[1])) +
                        (srgb8_to_linear(v[2]) + srgb8_to_linear(v[3]))) *
                       0.25f;
  const float encoded = std::clamp(linear_to_srgb(linear), 0.0f, 1.0f) * 255.0f;
  return uint8_t(std::lround(encoded));
}

uint8_t integer_mean(const uint8_t v[4]) {
  return uint8_t((unsigned(v[0]) + v[1] + v[2] + v[3] + 2u) / 4u);
}

}  // namespace

TextureLevel next_mip_level(const TextureLevel& in, bool srgb) {
  TextureLevel out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.rgba8.resize(size_t(out.width) * size_t(out.height) * 4);
  for (int j = 0; j < out.height; ++j) {
    const int y0 = std::min(2 * j, in.height - 1), y1 = std::min(2 * j + 1, in.height - 1);
    for (int i = 0; i < out.width; ++i) {
      const int x0 = std::min(2 * i, in.width - 1), x1 = std::min(2 * i + 1, in.width - 1);
      const size_t at[4] = {(size_t(y0) * size_t(in.width) + size_t(x0)) * 4,
                            (size_t(y0) * size_t(in.width) + size_t(x1)) * 4,
                            (size_t(y1) * size_t(in.width) + size_t(x0)) * 4,
                            (size_t(y1) * size_t(in.width) + size_t(x1)) * 4};
      uint8_t* o = &out.rgba8[(size_t(j) * size_t(out.width) + size_t(i)) * 4];
      for (int c = 0; c < 4; ++c) {
        const uint8_t v[4] = {in.rgba8[at[0] + size_t(c)], in.rgba8[at[1] + size_t(c)],
                              in.rgba8[at[2] + size_t(c)], in.rgba8[at[3] + size_t(c)]};
        o[c] = srgb && c < 3 ? srgb_mean(v) : integer_mean(v);
      }
    }
  }
  return out;
}

std::vector<TextureLevel> build_mip_chain(const Texture& texture, bool srgb) {
  std::vector<TextureLevel> chain;
  if (texture.width <= 0 || texture.height <= 0) return chain;
  const int levels = mip_level_count(texture.width, texture.height);
  TextureLevel level{texture.width, texture.height, texture.rgba8};
  for (int l = 1; l < levels; ++l) {
    level = next_mip_level(level, srgb);
    chain.push_back(level);
  }
  return chain;
}

void build_texture_mips(Scene& scene) {
  auto need = [&](const TextureRef& r, bool srgb) {
    if (!r.present() || size_t(r.texture) >= scene.textures.size()) return;
    Texture& t = scene.textures[size_t(r.texture)];
    std::vector<TextureLevel>& chain = t.mips[srgb ? 1 : 0];
    if (chain.empty()) chain = build_mip_chain(t, srgb);
  };
  for (const Material& m : scene.materials) {
    need(m.base_color_texture, true);
    need(m.emissive_texture, true);
    need(m.metallic_roughness_texture, false);
    need(m.normal_texture, false);
  }
}

const uint8_t* mip_level_texels(const Texture& texture, bool srgb, int level, int& width,
                                int& height) {
  if (level == 0) {
    width = texture.width;
    height = texture.height;
    return texture.rgba8.data();
  }
  const std::vector<TextureLevel>& chain = texture.mips[srgb ? 1 : 0];
  if (level < 0 || size_t(level) > chain.size()) return nullptr;
  const TextureLevel& l = chain[size_t(level) - 1];
  width = l.width;
  height = l.height;
  return l.rgba8.data();
}

}  // namespace vct
