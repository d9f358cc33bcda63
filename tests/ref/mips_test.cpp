// Mips on hand-made 2^3 and 4^3 volumes: isotropic box filter and anisotropic compositing.
#include <gtest/gtest.h>

#include "stages/mips.h"

namespace vct {
namespace {

TEST(Mips, IsotropicBoxFilterOf2Cubed) {
  Volume v(2, 2, 2, 4);
  for (int i = 0; i < 8; ++i) v.set_rgba(i & 1, (i >> 1) & 1, i >> 2, vec4(float(i), 0.0f, 1.0f, i < 4 ? 1.0f : 0.0f));
  const VoxelMips m = build_mips(v, false);
  ASSERT_EQ(m.iso.size(), 2u);
  EXPECT_EQ(m.iso[1].nx, 1);
  EXPECT_EQ(m.iso[1].rgba(0, 0, 0), vec4(3.5f, 0.0f, 1.0f, 0.5f));  // (0+..+7)/8, opacity averaged
  EXPECT_FALSE(m.anisotropic());
}

TEST(Mips, AnisotropicCompositesFrontToBackAlongEachDirection) {
  Volume v(2, 2, 2, 4);
  // x = 0 layer: red, half opaque; x = 1 layer: green, opaque.
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y) {
      v.set_rgba(0, y, z, vec4(1.0f, 0.0f, 0.0f, 0.5f));
      v.set_rgba(1, y, z, vec4(0.0f, 1.0f, 0.0f, 1.0f));
    }
  const VoxelMips m = build_mips(v, true);
  ASSERT_TRUE(m.anisotropic());
  ASSERT_EQ(m.aniso[kPosX].size(), 1u);
  // Looking along +x the red layer is in front: red + (1 - .5) green, alpha .5 + .5 * 1.
  EXPECT_EQ(m.aniso[kPosX][0].rgba(0, 0, 0), vec4(1.0f, 0.5f, 0.0f, 1.0f));
  // Looking along -x the opaque green layer hides the red one.
  EXPECT_EQ(m.aniso[kNegX][0].rgba(0, 0, 0), vec4(0.0f, 1.0f, 0.0f, 1.0f));
  // Along y and z each pair is (red, red) or (green, green): red .5 + .5 * red = 1.5 red, alpha .75.
  // Averaging two red pairs and two green pairs: ((1.5, 0, 0, .75) * 2 + (0, 1, 0, 1) * 2) / 4.
  for (int d : {kPosY, kNegY, kPosZ, kNegZ})
    EXPECT_EQ(m.aniso[size_t(d)][0].rgba(0, 0, 0), vec4(0.75f, 0.5f, 0.0f, 0.875f)) << d;
}

TEST(Mips, AlphaIsClampedAndLevelsChain) {
  Volume v(4, 4, 4, 4, 0.0f);
  // One opaque white voxel at (0,0,0) and one at (1,0,0) (same level-1 cell, one pair along x).
  v.set_rgba(0, 0, 0, vec4(1.0f, 1.0f, 1.0f, 1.0f));
  v.set_rgba(1, 0, 0, vec4(1.0f, 1.0f, 1.0f, 1.0f));
  // A super-opaque value (alpha 2, not physical) to check the clamp.
  v.set_rgba(3, 3, 3, vec4(0.0f, 0.0f, 0.0f, 2.0f));
  v.set_rgba(2, 3, 3, vec4(0.0f, 0.0f, 0.0f, 2.0f));
  v.set_rgba(3, 2, 3, vec4(0.0f, 0.0f, 0.0f, 2.0f));
  v.set_rgba(2, 2, 3, vec4(0.0f, 0.0f, 0.0f, 2.0f));
  const VoxelMips m = build_mips(v, true);
  ASSERT_EQ(m.iso.size(), 3u);
  ASSERT_EQ(m.aniso[kPosX].size(), 2u);
  // +x at level 1: the pair (front opaque) gives 1 in one of four pairs -> 0.25.
  EXPECT_EQ(m.aniso[kPosX][0].rgba(0, 0, 0), vec4(0.25f));
  // Along +y the two voxels are in different pairs: each pair front (1,1,1,1) -> (1+1)/4 = 0.5.
  EXPECT_EQ(m.aniso[kPosY][0].rgba(0, 0, 0), vec4(0.5f));
  // Cell (1,1,1) along -z: the four alpha-2 voxels (z = 3) are in front of empty ones:
  // 2 + (1 - 2) * 0 = 2 per pair, averaged 2, clamped to 1.
  EXPECT_EQ(m.aniso[kNegZ][0].rgba(1, 1, 1).a, 1.0f);
  // Level 2 of +x is built from level 1 of +x: cell (0,0,0) composites (0.25 front, 0 back).
  const vec4 l1 = m.aniso[kPosX][0].rgba(0, 0, 0);
  const vec4 expected = (l1 + (1.0f - l1.a) * m.aniso[kPosX][0].rgba(1, 0, 0) + m.aniso[kPosX][0].rgba(0, 1, 0) +
                         (1.0f - m.aniso[kPosX][0].rgba(0, 1, 0).a) * m.aniso[kPosX][0].rgba(1, 1, 0) +
                         m.aniso[kPosX][0].rgba(0, 0, 1) + (1.0f - m.aniso[kPosX][0].rgba(0, 0, 1).a) * m.aniso[kPosX][0].rgba(1, 0, 1) +
                         m.aniso[kPosX][0].rgba(0, 1, 1) + (1.0f - m.aniso[kPosX][0].rgba(0, 1, 1).a) * m.aniso[kPosX][0].rgba(1, 1, 1)) *
                        0.25f;
  vec4 got = m.aniso[kPosX][1].rgba(0, 0, 0);
  EXPECT_EQ(got.r, expected.r);
  EXPECT_EQ(got.a, std::min(expected.a, 1.0f));
  // Isotropic level 1 cell (0,0,0): two white voxels of eight.
  EXPECT_EQ(m.iso[1].rgba(0, 0, 0), vec4(0.25f));
}

TEST(Mips, MemoryReport) {
  Volume v(8, 8, 8, 4);
  const VoxelMips iso = build_mips(v, false), an = build_mips(v, true);
  const MipMemory mi = mips_memory(iso, VoxelStorage::Rgba8), ma = mips_memory(an, VoxelStorage::Rgba16f);
  EXPECT_EQ(mi.voxels, 512 + 64 + 8 + 1);
  EXPECT_EQ(mi.gpu_bytes, mi.voxels * 4);
  EXPECT_EQ(ma.voxels, 512 + 6 * (64 + 8 + 1));
  EXPECT_EQ(ma.gpu_bytes, ma.voxels * 8);
  EXPECT_EQ(ma.ref_bytes, ma.voxels * 16);
}

}  // namespace
}  // namespace vct
