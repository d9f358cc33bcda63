// A diffuse cone set given as data (settings diffuse_cone_set, cone_tangent_frame,
// cone_axis_offset_voxels; issue 21): the text's cones, in the declared tangent frame, with their
// own apertures and weights, and the source design's march (origin moved along the normal, first
// sample further along the axis). Small hand-computed cases on an 8^3 volume.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/declared_cones.h"
#include "core/error.h"
#include "stages/cone_sets.h"
#include "stages/mips.h"

namespace vct {
namespace {

// The source design's set (righier/gidemo voxelcone.frag TraceDiffuse: five cones, 30 degrees,
// summed).
constexpr const char* kGidemoCones = "0,0,1,30,1 1,0,1,30,1 -1,0,1,30,1 0,1,1,30,1 0,-1,1,30,1";

// N = 8, level 0 holds one opaque voxel of radiance 3 at `v`, the upper levels are empty: a
// sample at a level-0 texel centre reads exactly that texel.
VoxelMips one_voxel(const ivec3& v) {
  VoxelMips m;
  for (int n = 8; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4));
  m.iso[0].set_rgba(v.x, v.y, v.z, vec4(3.0f, 3.0f, 3.0f, 1.0f));
  return m;
}

TEST(DeclaredCones, ParsesTheSourceDesignsSetAndNormalises) {
  const std::vector<DeclaredCone> c = parse_declared_cones(kGidemoCones);
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[0].direction, vec3(0.0f, 0.0f, 1.0f));
  EXPECT_FLOAT_EQ(c[1].direction.x, 0.70710678f);
  EXPECT_FLOAT_EQ(c[1].direction.z, 0.70710678f);
  EXPECT_FLOAT_EQ(c[4].direction.y, -0.70710678f);
  EXPECT_EQ(c[3].aperture_deg, 30.0f);
  EXPECT_EQ(c[2].weight, 1.0f);
  EXPECT_TRUE(parse_declared_cones("").empty());
}

TEST(DeclaredCones, RejectsMalformedEntries) {
  for (const char* bad : {"0,0,1,30", "0,0,1,30,1,2", "0,0,-1,30,1", "0,0,0,30,1", "0,0,1,0,1", "0,0,1,180,1",
                          "0,0,1,30,-1", "0,0,1,30,x", "0,0,1,nan,1"})
    EXPECT_THROW(parse_declared_cones(bad), InputError) << bad;
  std::string seventeen;
  for (int i = 0; i < 17; ++i) seventeen += "0,0,1,30,1 ";
  EXPECT_THROW(parse_declared_cones(seventeen), InputError);
  Settings s;
  s.vct.diffuse_cone_set = "0,0,1,30";
  EXPECT_THROW(validate_settings(s), InputError);
}

TEST(DeclaredCones, CrossHintFrameIsTheSourceDesignsByHand) {
  // n = +z: n x (0.1, 0, 1) = (0, 0.1, 0), so t = +y and b = n x t = -x.
  const sh::Frame f = diffuse_cone_frame(vec3(0.0f, 0.0f, 1.0f), ConeTangentFrame::CrossHint);
  EXPECT_FLOAT_EQ(f.t.y, 1.0f);
  EXPECT_FLOAT_EQ(f.b.x, -1.0f);
  EXPECT_NEAR(glm::length(f.t - vec3(0, 1, 0)) + glm::length(f.b - vec3(-1, 0, 0)), 0.0f, 1e-7f);
  // n along the hint itself (|n . hint| = 1 >= 0.999): the fallback (1, 0, 0); n x x = (0, n.z, 0).
  const vec3 n = glm::normalize(vec3(0.1f, 0.0f, 1.0f));
  const sh::Frame g = diffuse_cone_frame(n, ConeTangentFrame::CrossHint);
  EXPECT_NEAR(glm::length(g.t - vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(g.b - vec3(-n.z, 0.0f, n.x)), 0.0f, 1e-6f);
  // Ours at +z: t = +x, b = +y (sh::frame_from_normal).
  const sh::Frame h = diffuse_cone_frame(vec3(0.0f, 0.0f, 1.0f), ConeTangentFrame::Branchless);
  EXPECT_EQ(h.t, vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(h.b, vec3(0.0f, 1.0f, 0.0f));
}

// One narrow declared cone "1,0,1" (45 degrees toward the tangent) of weight 2 at voxel (4,4,1)'s
// centre with n = +z, started the source design's way: origin one voxel along n (4.5, 4.5, 2.5),
// then sqrt(2) voxels along the axis. In the cross-hint frame t = +y, so the axis is (0,1,1)/sqrt 2
// and the first sample is voxel (4,5,3)'s centre; in ours t = +x and it is voxel (5,4,3)'s.
VctSettings single_cone(ConeTangentFrame frame) {
  VctSettings s;
  s.diffuse_cone_set = "1,0,1,1,2";
  s.cone_tangent_frame = frame;
  s.cone_start = ConeStart::Normal;
  s.cone_offset_voxels = 1.0f;
  s.cone_axis_offset_voxels = std::sqrt(2.0f);
  s.cone_quality = 1.0f;
  return s;
}

TEST(DeclaredCones, SingleConeGoesWhereItsFrameSaysWithItsWeight) {
  const VoxelMips m = one_voxel(ivec3(4, 5, 3));
  const vec3 p = vec3(4.5f, 4.5f, 1.5f) / 8.0f, n(0.0f, 0.0f, 1.0f);
  std::vector<std::vector<ConeSample>> rec;
  const DiffuseConeSet hit = trace_diffuse_cones(m, VoxelVolume{}, single_cone(ConeTangentFrame::CrossHint), p, n,
                                                 0.0f, 0.0f, &rec);
  ASSERT_EQ(hit.count, 1);
  EXPECT_FLOAT_EQ(hit.geometry[0].origin.z, 2.5f / 8.0f);
  ASSERT_FALSE(rec[0].empty());
  EXPECT_FLOAT_EQ(rec[0][0].distance, std::sqrt(2.0f) / 8.0f);
  EXPECT_NEAR(rec[0][0].position.y * 8.0f, 5.5f, 1e-5f);
  EXPECT_NEAR(rec[0][0].position.z * 8.0f, 3.5f, 1e-5f);
  // Diameter max(1/8, 2 t tan(0.5 deg)) = 1/8: a level-0 read of the voxel, to within the
  // position's rounding (~1e-6 of a texel).
  EXPECT_FLOAT_EQ(rec[0][0].diameter, 1.0f / 8.0f);
  EXPECT_NEAR(hit.cones[0].x, 3.0f, 1e-4f);
  EXPECT_EQ(hit.weights[0], 2.0f);
  EXPECT_NEAR(hit.radiance.x, 6.0f, 2e-4f);
  const DiffuseConeSet miss = trace_diffuse_cones(m, VoxelVolume{}, single_cone(ConeTangentFrame::Branchless), p, n,
                                                  0.0f, 0.0f);
  EXPECT_NEAR(miss.radiance.x, 0.0f, 1e-4f);
}

TEST(DeclaredCones, DeclaredApertureSetsTheDiameter) {
  // One cone along n, 90 degrees, started 2 voxels along its axis: the first diameter is
  // 2 t tan(45 deg) = 2 * 2/8 = 0.5, lod log2(0.5 * 8) = 2.
  VctSettings s;
  s.diffuse_cone_set = "0,0,1,90,1";
  s.cone_offset_voxels = 2.0f;
  std::vector<std::vector<ConeSample>> rec;
  trace_diffuse_cones(one_voxel(ivec3(0, 0, 0)), VoxelVolume{}, s, vec3(4.5f, 4.5f, 1.5f) / 8.0f,
                      vec3(0.0f, 0.0f, 1.0f), 0.0f, 0.0f, &rec);
  ASSERT_FALSE(rec[0].empty());
  EXPECT_FLOAT_EQ(rec[0][0].diameter, 0.5f);
  EXPECT_FLOAT_EQ(rec[0][0].lod, 2.0f);
}

TEST(DeclaredCones, SourceDesignsMarchStepsByHand) {
  // gidemo's ConeTracing(pos + 2/N n, dir, 2 tan(15 deg), offset 2, quality 0.7): t0 = 2/N, then
  // t += 0.7 max(1/N, t 2 tan(15 deg)). Its slope floor max(1/N, 2 tan(a/2)) changes nothing for
  // 30 degrees (0.536 > 1/N).
  VctSettings s;
  s.diffuse_cone_set = kGidemoCones;
  s.cone_tangent_frame = ConeTangentFrame::CrossHint;
  s.cone_start = ConeStart::Normal;
  s.cone_offset_voxels = 2.0f;
  s.cone_axis_offset_voxels = 2.0f;
  s.cone_quality = 0.7f;
  std::vector<std::vector<ConeSample>> rec;
  const DiffuseConeSet set = trace_diffuse_cones(one_voxel(ivec3(0, 0, 0)), VoxelVolume{}, s,
                                                 vec3(4.5f, 4.5f, 0.5f) / 8.0f, vec3(0, 0, 1), 0.0f, 0.0f, &rec);
  ASSERT_EQ(set.count, 5);
  EXPECT_FLOAT_EQ(set.geometry[0].origin.z, 2.5f / 8.0f);
  double t = 2.0 / 8.0;
  const double slope = 2.0 * std::tan(15.0 * 3.14159265358979 / 180.0);
  ASSERT_GE(rec[0].size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(rec[0][k].distance, t, 1e-6) << k;
    t += 0.7 * std::max(1.0 / 8.0, t * slope);
  }
  // Every weight 1: the plain sum; the tilted cones in the cross-hint frame (t = +y, b = -x).
  for (int i = 0; i < 5; ++i) EXPECT_EQ(set.weights[size_t(i)], 1.0f);
  EXPECT_NEAR(set.geometry[1].direction.y, 0.70710678f, 1e-6f);
  EXPECT_NEAR(set.geometry[3].direction.x, -0.70710678f, 1e-6f);
}

TEST(DeclaredCones, OraclesSetWrittenAsDataTracesTheSameLight) {
  // The default set (5 cones at 45 degrees, cosine weights 1/T and cos45/T, T = 1 + 4 cos 45)
  // declared as data in our frame gives the same radiance on a non-uniform volume, up to the
  // directions' rounding (cos(pi/2) is -4e-8 in float, not 0) and the weights' 6 decimals
  // (5e-7 each, times 5 cones and radiance < 1: < 3e-6, inside the 1e-5 allowed).
  VoxelMips m;
  Volume base(8, 8, 8, 4);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        if ((x * 7 + y * 3 + z * 5) % 4 == 0) base.set_rgba(x, y, z, vec4(0.1f * float(x), 0.2f, 0.05f * float(z), 1.0f));
  m = build_mips(base, false);
  const double c = std::cos(3.14159265358979 / 4.0), total = 1.0 + 4.0 * c;
  const std::string w0 = std::to_string(1.0 / total), w1 = std::to_string(c / total);
  VctSettings declared;
  declared.diffuse_cone_set = "0,0,1,30," + w0 + " 1,0,1,30," + w1 + " 0,1,1,30," + w1 + " -1,0,1,30," + w1 +
                              " 0,-1,1,30," + w1;
  for (const vec3& n : {vec3(0, 1, 0), glm::normalize(vec3(0.3f, 0.4f, 0.8f))}) {
    const vec3 a = trace_diffuse_cones(m, VoxelVolume{}, VctSettings{}, vec3(0.4f), n, 0.0f).radiance;
    const vec3 b = trace_diffuse_cones(m, VoxelVolume{}, declared, vec3(0.4f), n, 0.0f).radiance;
    EXPECT_GT(a.x, 0.01f);
    EXPECT_NEAR(b.x, a.x, 1e-5f * (1.0f + a.x));
    EXPECT_NEAR(b.z, a.z, 1e-5f * (1.0f + a.z));
  }
}

TEST(DeclaredCones, AxisOffsetNeedsTheNormalStart) {
  Settings s;
  s.vct.cone_axis_offset_voxels = 2.0f;
  EXPECT_THROW(validate_settings(s), InputError);
  s.vct.cone_start = ConeStart::Normal;
  EXPECT_NO_THROW(validate_settings(s));
}

}  // namespace
}  // namespace vct
