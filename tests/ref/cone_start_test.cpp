// The cone start convention (setting cone_start, issue 21): `axis` starts each cone
// cone_offset_voxels along its own axis, `normal` moves the origin that far along the surface
// normal and marches from t = 0 (the source design's). A grazing specular cone, by hand, where the
// two see different voxels.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "stages/cone_sets.h"
#include "stages/cone_trace.h"

namespace vct {
namespace {

// N = 8, one emissive opaque voxel (4,4,4) of radiance 3 in level 0 and empty upper levels, so a
// lod-0 sample reads only level 0 (narrow cone: diameter = max(1/8, 2 t tan(a/2)) = 1/8 while
// tan(a/2) < 1/16 over the whole volume).
VoxelMips one_voxel_level0() {
  VoxelMips m;
  for (int n = 8; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4));
  m.iso[0].set_rgba(4, 4, 4, vec4(3.0f, 3.0f, 3.0f, 1.0f));
  return m;
}

// Surface point at the centre of voxel (1,4,4) (texture = world: default volume), normal +y,
// viewed from +x's opposite side so reflect(-v, n) = +x: the cone runs along row y = 4.5 / 8.
struct Grazing {
  vec3 p{1.5f / 8.0f, 4.5f / 8.0f, 4.5f / 8.0f};
  vec3 n{0.0f, 1.0f, 0.0f};
  vec3 v{-1.0f, 0.0f, 0.0f};
  float roughness = 0.1f;  // aperture 2 atan(0.01): tan(a/2) ~ 0.01
};

VctSettings one_voxel_offset(ConeStart start) {
  VctSettings s;
  s.cone_offset_voxels = 1.0f;
  s.cone_quality = 1.0f;  // steps of one voxel (diameter 1/8)
  s.cone_start = start;
  return s;
}

TEST(ConeStart, AxisStartsOneVoxelAlongTheConeAndHitsTheVoxel) {
  const VoxelMips m = one_voxel_level0();
  const Grazing g;
  std::vector<ConeSample> rec;
  const vec4 r = trace_specular_cone(m, VoxelVolume{}, one_voxel_offset(ConeStart::Axis), g.p, g.n, g.v,
                                     g.roughness, &rec);
  // Samples at x = 2.5, 3.5, 4.5 voxels on row y = 4.5: texel centres, the third is the voxel.
  ASSERT_EQ(rec.size(), 3u);
  EXPECT_FLOAT_EQ(rec[0].distance, 1.0f / 8.0f);
  EXPECT_FLOAT_EQ(rec[0].position.x, 2.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[0].position.y, 4.5f / 8.0f);
  EXPECT_FLOAT_EQ(r.x, 3.0f);
  EXPECT_FLOAT_EQ(r.w, 1.0f);
}

TEST(ConeStart, NormalStartsOneVoxelAboveTheSurfaceAndMissesTheVoxel) {
  const VoxelMips m = one_voxel_level0();
  const Grazing g;
  std::vector<ConeSample> rec;
  const vec4 r = trace_specular_cone(m, VoxelVolume{}, one_voxel_offset(ConeStart::Normal), g.p, g.n, g.v,
                                     g.roughness, &rec);
  // Origin (1.5, 5.5, 4.5) voxels, t = 0: samples x = 1.5 .. 7.5 on row y = 5.5, texel centres of
  // row 5, which is empty; x = 8.5 leaves the volume. Seven samples, nothing accumulated.
  ASSERT_EQ(rec.size(), 7u);
  EXPECT_FLOAT_EQ(rec[0].distance, 0.0f);
  EXPECT_FLOAT_EQ(rec[0].diameter, 1.0f / 8.0f);
  EXPECT_FLOAT_EQ(rec[0].position.x, 1.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[0].position.y, 5.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[6].position.x, 7.5f / 8.0f);
  EXPECT_EQ(r, vec4(0.0f));
}

TEST(ConeStart, DiffuseConesOfTheFrameUseTheNormalOrigin) {
  // One diffuse cone along the normal -x from voxel (5,4,4)'s centre: axis starts at x = 4.5
  // (the voxel, full radiance); normal moves the origin to x = 4.5 and marches from t = 0, so its
  // first sample is the voxel too, with a one-voxel diameter. Both see 3; the record says where.
  const VoxelMips m = one_voxel_level0();
  VctSettings s = one_voxel_offset(ConeStart::Normal);
  s.diffuse_cone_count = 1;
  std::vector<std::vector<ConeSample>> rec;
  const DiffuseConeSet set = trace_diffuse_cones(m, VoxelVolume{}, s, vec3(5.5f, 4.5f, 4.5f) / 8.0f,
                                                 vec3(-1.0f, 0.0f, 0.0f), 0.0f, 0.0f, &rec);
  ASSERT_EQ(rec.size(), 1u);
  ASSERT_FALSE(rec[0].empty());
  EXPECT_FLOAT_EQ(set.geometry[0].origin.x, 4.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[0][0].distance, 0.0f);
  EXPECT_FLOAT_EQ(set.cones[0].x, 3.0f);
}

TEST(ConeStart, SettingRoundTripsAndRejectsUnknownNames) {
  VctSettings s;
  from_json(nlohmann::json{{"cone_start", "normal"}}, s);
  EXPECT_EQ(s.cone_start, ConeStart::Normal);
  nlohmann::json back;
  to_json(back, s);
  EXPECT_EQ(back.at("cone_start"), "normal");
  EXPECT_THROW(from_json(nlohmann::json{{"cone_start", "tangent"}}, s), InputError);
}

}  // namespace
}  // namespace vct
