// Cone marching against hand computations: one emissive voxel, the border, an empty volume.
#include <gtest/gtest.h>

#include <cmath>

#include "stages/cone_sets.h"
#include "stages/cone_trace.h"
#include "stages/indirect_pass.h"

namespace vct {
namespace {

VoxelMips single_voxel_mips(int n, ivec3 voxel, float radiance) {
  VoxelMips m;
  m.iso.push_back(Volume(n, n, n, 4));
  m.iso[0].set_rgba(voxel.x, voxel.y, voxel.z, vec4(vec3(radiance), 1.0f));
  // Box-filtered levels by hand: the one voxel's value divided by 8 per level.
  float scale = 1.0f;
  for (int size = n / 2; size >= 1; size /= 2) {
    scale /= 8.0f;
    voxel /= 2;
    Volume level(size, size, size, 4);
    level.set_rgba(voxel.x, voxel.y, voxel.z, vec4(vec3(radiance), 1.0f) * scale);
    m.iso.push_back(level);
  }
  return m;
}

TEST(ConeTrace, NarrowConeHitsTheVoxelAndStops) {
  const VoxelMips m = single_voxel_mips(8, ivec3(4, 4, 4), 3.0f);
  Cone cone{vec3(1.5f / 8.0f, 4.5f / 8.0f, 4.5f / 8.0f), vec3(1.0f, 0.0f, 0.0f), 0.01f};
  MarchParams p;
  p.start_offset = 1.0f / 8.0f;
  p.quality = 1.0f;  // one voxel per step: samples at texel centres x = 2.5, 3.5, 4.5 voxels
  std::vector<ConeSample> rec;
  const vec4 r = trace_cone(m, cone, p, &rec);
  EXPECT_FLOAT_EQ(r.x, 3.0f);
  EXPECT_FLOAT_EQ(r.w, 1.0f);
  ASSERT_EQ(rec.size(), 3u);  // stops at full opacity
  EXPECT_FLOAT_EQ(rec[2].distance, 3.0f / 8.0f);
  EXPECT_FLOAT_EQ(rec[2].lod, 0.0f);
}

TEST(ConeTrace, HalfTexelOffsetAccumulatesFrontToBack) {
  const VoxelMips m = single_voxel_mips(8, ivec3(4, 4, 4), 2.0f);
  // Samples fall halfway between texel centres along x: 3|4 gives (1, 0.5), 4|5 gives (1, 0.5).
  Cone cone{vec3(1.0f / 8.0f, 4.5f / 8.0f, 4.5f / 8.0f), vec3(1.0f, 0.0f, 0.0f), 0.01f};
  MarchParams p;
  p.start_offset = 3.0f / 8.0f;
  p.quality = 1.0f;
  const vec4 r = trace_cone(m, cone, p);
  // c = 1 + (1 - 0.5) * 1 = 1.5; a = 0.5 + 0.5 * 0.5 = 0.75 (premultiplied rgb).
  EXPECT_FLOAT_EQ(r.x, 1.5f);
  EXPECT_FLOAT_EQ(r.w, 0.75f);
}

TEST(ConeTrace, WideConeReadsCoarserLevelByHand) {
  // N = 4, voxel (2,2,2) radiance E; level 1 holds E/8 at (1,1,1).
  const float e = 8.0f;
  const VoxelMips m = single_voxel_mips(4, ivec3(2, 2, 2), e);
  // tan(aperture/2) = 0.5, so diameter = max(1/4, t): t = 1/4 -> lod 0 at x = 3/8 (empty);
  // t = 1/2 -> lod 1 at x = 5/8: level-1 weights 0.75^3 on texel (1,1,1); then x = 9/8 leaves.
  Cone cone{vec3(0.125f, 0.625f, 0.625f), vec3(1.0f, 0.0f, 0.0f), 2.0f * std::atan(0.5f)};
  MarchParams p;
  p.start_offset = 0.25f;
  p.quality = 1.0f;
  std::vector<ConeSample> rec;
  const vec4 r = trace_cone(m, cone, p, &rec);
  ASSERT_EQ(rec.size(), 2u);
  EXPECT_NEAR(rec[1].lod, 1.0f, 1e-6f);
  EXPECT_NEAR(r.x, 0.421875f * e / 8.0f, 1e-6f);
  EXPECT_NEAR(r.w, 0.421875f / 8.0f, 1e-6f);
}

TEST(ConeTrace, EmptyVolumeGivesZeroIndirect) {
  VoxelMips m;
  for (int n = 16; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4));
  VctSettings s;
  VoxelVolume vol;
  const DiffuseConeSet set = trace_diffuse_cones(m, vol, s, vec3(0.5f), vec3(0.0f, 1.0f, 0.0f), 0.3f);
  EXPECT_EQ(set.radiance, vec3(0.0f));
  EXPECT_EQ(trace_specular_cone(m, vol, s, vec3(0.5f), vec3(0, 1, 0), glm::normalize(vec3(1, 1, 0)), 0.2f), vec4(0.0f));
  Light light;
  light.position = vec3(0.8f);
  EXPECT_FLOAT_EQ(trace_shadow_cone(m, vol, s, vec3(0.2f), light), 1.0f);
  light.kind = LightKind::Directional;
  EXPECT_FLOAT_EQ(trace_shadow_cone(m, vol, s, vec3(0.2f), light), 1.0f);

  // Through the whole image pass as well.
  GBuffer g;
  g.coverage = Image(2, 1, 1, 1.0f);
  g.position = Image(2, 1, 3, 0.5f);
  g.normal = Image(2, 1, 3, 0.0f);
  g.normal.set_rgb(0, 0, vec3(0, 0, 1));
  g.normal.set_rgb(1, 0, vec3(0, 1, 0));
  g.material = Image(2, 1, 4, 0.5f);
  Scene scene;
  scene.camera.position = vec3(0.5f, 0.5f, 3.0f);
  const IndirectImages ind = trace_indirect(scene, g, m, s);
  for (float v : ind.diffuse.data) EXPECT_EQ(v, 0.0f);
  for (float v : ind.specular.data) EXPECT_EQ(v, 0.0f);
}

TEST(ConeTrace, CosineWeightedDiffuseSetOfAConstantVolumeIsThatConstant) {
  // Every cone sees the same uniform radiance L with opacity 1 at its first sample, so the
  // cosine-weighted mean is L and the seed's plain sum is 5 L.
  VoxelMips m;
  for (int n = 16; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4, 1.0f));
  for (Volume& v : m.iso)
    for (size_t i = 0; i < v.voxel_count(); ++i) v.data[i * 4] = 0.25f;  // R = 0.25, G = B = A = 1
  VctSettings s;
  VoxelVolume vol;
  const vec3 n = glm::normalize(vec3(0.3f, 0.4f, 0.8f));
  EXPECT_NEAR(trace_diffuse_cones(m, vol, s, vec3(0.5f), n, 0.0f).radiance.x, 0.25f, 1e-6f);
  s.diffuse_weighting = DiffuseWeighting::SeedSum;
  EXPECT_NEAR(trace_diffuse_cones(m, vol, s, vec3(0.5f), n, 0.0f).radiance.y, 5.0f, 1e-5f);
}

}  // namespace
}  // namespace vct
