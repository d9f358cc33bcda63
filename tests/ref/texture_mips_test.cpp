// The CPU mip chain (scene/texture_mips.h) against hand-computed levels: the 2x2 box filter with
// rounding, sRGB averaged in linear light, non-power-of-two sizes, and the scene-wide builder.
#include <gtest/gtest.h>

#include "scene/texture_mips.h"
#include "scene/texture_sample.h"

namespace vct {
namespace {

Texture texture(int w, int h, std::vector<uint8_t> rgba) {
  Texture t;
  t.width = w;
  t.height = h;
  t.rgba8 = std::move(rgba);
  return t;
}

TEST(TextureMips, LevelCountFollowsTheLargerAxis) {
  EXPECT_EQ(mip_level_count(1, 1), 1);
  EXPECT_EQ(mip_level_count(2, 2), 2);
  EXPECT_EQ(mip_level_count(256, 256), 9);
  EXPECT_EQ(mip_level_count(5, 3), 3);  // 5x3 -> 2x1 -> 1x1
  EXPECT_EQ(mip_level_count(64, 1), 7);
}

TEST(TextureMips, LinearTwoByTwoIsTheRoundedMean) {
  // Texels (R, G, B, A): R sums to 1 + 2 + 3 + 4 = 10 -> 10/4 = 2.5 rounds half up to 3;
  // G 0 + 0 + 0 + 1 = 1 -> 0.25 -> 0; B 255 x 4 -> 255; A 0 + 255 + 255 + 255 = 765 -> 191.25 ->
  // 191.
  const Texture t = texture(2, 2, {1, 0, 255, 0, 2, 0, 255, 255, 3, 0, 255, 255, 4, 1, 255, 255});
  const std::vector<TextureLevel> chain = build_mip_chain(t, false);
  ASSERT_EQ(chain.size(), 1u);
  EXPECT_EQ(chain[0].width, 1);
  EXPECT_EQ(chain[0].height, 1);
  EXPECT_EQ(chain[0].rgba8, (std::vector<uint8_t>{3, 0, 255, 191}));
}

TEST(TextureMips, SrgbIsAveragedInLinearLight) {
  // Black and white: linear mean 0.5, re-encoded 1.055 * 0.5^(1/2.4) - 0.055 = 0.735357 -> 187.516
  // -> 188 (a naive 8-bit mean would give 128). Alpha stays linear: (0 + 0 + 255 + 255 + 2) / 4 =
  // 128.
  const Texture t = texture(2, 2, {0, 0, 0, 0, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255, 255});
  const std::vector<TextureLevel> chain = build_mip_chain(t, true);
  ASSERT_EQ(chain.size(), 1u);
  EXPECT_EQ(chain[0].rgba8, (std::vector<uint8_t>{188, 188, 188, 128}));
  // The checker greys: light (200, 190, 170) and dark (90, 80, 70) average to
  // (157.58, 148.33, 132.23) -> (158, 148, 132) in linear light, not (145, 135, 120).
  const Texture c =
      texture(2, 2, {200, 190, 170, 255, 90, 80, 70, 255, 90, 80, 70, 255, 200, 190, 170, 255});
  EXPECT_EQ(build_mip_chain(c, true)[0].rgba8, (std::vector<uint8_t>{158, 148, 132, 255}));
  EXPECT_EQ(build_mip_chain(c, false)[0].rgba8, (std::vector<uint8_t>{145, 135, 120, 255}));
}

TEST(TextureMips, NonPowerOfTwoDropsTheLastRowAndColumn) {
  // 3x3, R = 10 * row + column: level 1 is floor(3/2) = 1 x 1, averaging texels (0..1) x (0..1)
  // only: (0 + 1 + 10 + 11 + 2) / 4 = 6. The last row and column do not contribute.
  std::vector<uint8_t> px;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) px.insert(px.end(), {uint8_t(10 * y + x), 0, 0, 255});
  const std::vector<TextureLevel> chain = build_mip_chain(texture(3, 3, px), false);
  ASSERT_EQ(chain.size(), 1u);
  EXPECT_EQ(chain[0].rgba8[0], 6);
  // 4x1 -> 2x1 -> 1x1: a one-texel axis stays 1 and its texel is used twice.
  const std::vector<TextureLevel> strip = build_mip_chain(
      texture(4, 1, {0, 0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255, 255, 0, 0, 255}), false);
  ASSERT_EQ(strip.size(), 2u);
  EXPECT_EQ(strip[0].width, 2);
  EXPECT_EQ(strip[0].height, 1);
  EXPECT_EQ(strip[0].rgba8[0], 50);   // (0 + 100 + 0 + 100 + 2) / 4 = 50.5 -> 50
  EXPECT_EQ(strip[0].rgba8[4], 228);  // (200 + 255) * 2 / 4 = 227.5 -> 228
  EXPECT_EQ(strip[1].rgba8[0], 139);  // (50 + 228) * 2 / 4 = 139
}

TEST(TextureMips, SceneBuildsOneChainPerEncodingItReads) {
  Scene s;
  s.textures.push_back(texture(4, 4, std::vector<uint8_t>(64, 200)));
  s.textures.push_back(texture(2, 2, std::vector<uint8_t>(16, 10)));
  s.textures.push_back(texture(2, 2, std::vector<uint8_t>(16, 10)));  // unused
  Material m;
  m.base_color_texture.texture = 0;  // sRGB
  m.normal_texture.texture = 0;      // and linear
  m.metallic_roughness_texture.texture = 1;
  s.materials.push_back(m);
  build_texture_mips(s);
  EXPECT_EQ(s.textures[0].mips[0].size(), 2u);
  EXPECT_EQ(s.textures[0].mips[1].size(), 2u);
  EXPECT_EQ(s.textures[1].mips[0].size(), 1u);
  EXPECT_TRUE(s.textures[1].mips[1].empty());
  EXPECT_TRUE(s.textures[2].mips[0].empty() && s.textures[2].mips[1].empty());
  EXPECT_EQ(available_levels(s.textures[0], true), 3);
  EXPECT_EQ(available_levels(s.textures[2], false), 1);
}

}  // namespace
}  // namespace vct
