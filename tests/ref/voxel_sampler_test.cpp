// The voxel sampler against values computed by hand from the GL specification's formulas.
#include <gtest/gtest.h>

#include "stages/voxel_sampler.h"

namespace vct {
namespace {

Volume ramp_level() {
  // 2^3, texel (i,j,k) = (i + 2j + 4k + 1) in every channel, alpha = the same.
  Volume v(2, 2, 2, 4);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) v.set_rgba(i, j, k, vec4(float(i + 2 * j + 4 * k + 1)));
  return v;
}

TEST(VoxelSampler, TexelCentreReturnsTheTexel) {
  const Volume v = ramp_level();
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.25f, 0.25f, 0.25f)).x, 1.0f);
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.75f, 0.75f, 0.75f)).x, 8.0f);
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.75f, 0.25f, 0.75f)).x, 6.0f);
}

TEST(VoxelSampler, TrilinearWeightsFollowTexelCentres) {
  const Volume v = ramp_level();
  // Centre of the volume: the mean of all eight texels, (1+...+8)/8 = 4.5.
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.5f)).x, 4.5f);
  // x = 0.375: u = 0.375*2 - 0.5 = 0.25 -> 0.75*t(0) + 0.25*t(1) = 0.75*1 + 0.25*2.
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.375f, 0.25f, 0.25f)).x, 1.25f);
}

TEST(VoxelSampler, ClampToBorderMixesInZero) {
  const Volume v = ramp_level();
  // x = 0: u = -0.5 -> i0 = -1 (border 0) and i0+1 = 0, half each.
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(0.0f, 0.25f, 0.25f)).x, 0.5f);
  // Far outside: only border texels.
  EXPECT_EQ(sample_level_trilinear(v, vec3(3.0f, 0.5f, 0.5f)), vec4(0.0f));
  // Corner (1,1,1): u = 1.5 -> texel 1 and border, weight 1/2 per axis: 8 * 1/8 = 1.
  EXPECT_FLOAT_EQ(sample_level_trilinear(v, vec3(1.0f)).w, 1.0f);
}

VoxelMips constant_mips(const float values[3]) {
  VoxelMips m;
  m.iso.push_back(Volume(4, 4, 4, 4, values[0]));
  m.iso.push_back(Volume(2, 2, 2, 4, values[1]));
  m.iso.push_back(Volume(1, 1, 1, 4, values[2]));
  return m;
}

TEST(VoxelSampler, LinearMipmapLinearBlendsNeighbourLevelsAndClampsLod) {
  const float values[3] = {1.0f, 3.0f, 5.0f};
  const VoxelMips m = constant_mips(values);
  const vec3 c(0.5f), d(0.0f, 0.0f, 1.0f);
  EXPECT_FLOAT_EQ(sample_voxels(m, c, -2.0f, d).x, 1.0f);   // clamped to level 0
  EXPECT_FLOAT_EQ(sample_voxels(m, c, 0.25f, d).x, 1.5f);   // 0.75*1 + 0.25*3
  EXPECT_FLOAT_EQ(sample_voxels(m, c, 1.5f, d).x, 4.0f);    // 0.5*3 + 0.5*5
  EXPECT_FLOAT_EQ(sample_voxels(m, c, 2.0f, d).x, 5.0f);    // last level
  EXPECT_FLOAT_EQ(sample_voxels(m, c, 9.0f, d).x, 5.0f);    // clamped to the last level
  EXPECT_EQ(max_mip_level(m), 2);
}

TEST(VoxelSampler, AnisotropicBlendsFacingVolumesBySquaredDirection) {
  VoxelMips m;
  m.iso.push_back(Volume(4, 4, 4, 4, 2.0f));
  m.iso.push_back(Volume(2, 2, 2, 4, 0.0f));
  for (int d = 0; d < 6; ++d) {
    m.aniso[size_t(d)].push_back(Volume(2, 2, 2, 4, float(10 * (d + 1))));  // posx 10, negx 20, ...
    m.aniso[size_t(d)].push_back(Volume(1, 1, 1, 4, float(100 * (d + 1))));
  }
  ASSERT_TRUE(m.anisotropic());
  EXPECT_EQ(max_mip_level(m), 2);
  const vec3 c(0.5f);
  const vec3 dir = glm::normalize(vec3(1.0f, -1.0f, 0.0f));  // +x and -y, weight 1/2 each
  // lod 1: 0.5*posx(10) + 0.5*negy(40) = 25.
  EXPECT_NEAR(sample_voxels(m, c, 1.0f, dir).x, 25.0f, 1e-5f);
  // lod 0.5: half the shared base (2) and half the level-1 blend (25).
  EXPECT_NEAR(sample_voxels(m, c, 0.5f, dir).x, 13.5f, 1e-5f);
  // lod 0: the base alone, whatever the direction.
  EXPECT_NEAR(sample_voxels(m, c, 0.0f, dir).x, 2.0f, 1e-6f);
  // lod 1.5 along -z only: 0.5*negz level1 (60) + 0.5*negz level2 (600).
  EXPECT_NEAR(sample_voxels(m, c, 1.5f, vec3(0.0f, 0.0f, -1.0f)).x, 330.0f, 1e-4f);
}

}  // namespace
}  // namespace vct
