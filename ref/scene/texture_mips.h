// Mip chains of material textures, built once on the CPU and uploaded level by level to GL
// (gl/gl_scene.cpp), so both backends filter identical bits (docs/scenes.md, "Textures").
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace vct {

/// Number of levels of a complete chain for a width x height level 0: GL 4.5 §8.14.3,
/// floor(log2(max(w, h))) + 1.
int mip_level_count(int width, int height);

/// The next level of `level`: GL's size max(1, floor(size / 2)) per axis; output texel (i, j)
/// is the 2x2 box mean of input texels {2i, 2i+1} x {2j, 2j+1}, where an index beyond the input
/// (an axis of size 1) repeats the last texel. An odd size > 1 drops its last row/column: each
/// output texel averages exactly its own four inputs, none is shared. sRGB (`srgb`): RGB decoded
/// to linear, averaged, re-encoded and rounded to the nearest 8-bit value; alpha (and every
/// channel of a linear texture) is the integer mean rounded half up, (a + b + c + d + 2) / 4.
TextureLevel next_mip_level(const TextureLevel& level, bool srgb);

/// Levels 1..q of `texture` (level 0 is Texture::rgba8), q = mip_level_count - 1.
std::vector<TextureLevel> build_mip_chain(const Texture& texture, bool srgb);

/// Builds Texture::mips for every way a material of `scene` reads each texture (base colour and
/// emissive: sRGB; metallic-roughness and normal: linear). Chains already built are kept.
void build_texture_mips(Scene& scene);

/// Level `level` of `texture` as read with encoding `srgb` (0 = level 0); nullptr if absent.
const uint8_t* mip_level_texels(const Texture& texture, bool srgb, int level, int& width,
                                int& height);

/// Levels available for `srgb` reads: 1 + the chain built for that encoding.
inline int available_levels(const Texture& texture, bool srgb) {
  return 1 + int(texture.mips[srgb ? 1 : 0].size());
}

}  // namespace vct
