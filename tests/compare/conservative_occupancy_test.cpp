// The conservative-mode occupancy judge (compare/conservative_occupancy.h): the dilated
// triangle-box test by hand, and synthetic occupancies against the exact voxelizer's set: one
// voxel missing -> FAIL naming it, an extra voxel beyond the bound -> FAIL, within it -> pass.
#include <gtest/gtest.h>

#include "compare/conservative_occupancy.h"
#include "scene/scene.h"
#include "stages/voxelize.h"

namespace vct::cmp {
namespace {

using glm::dvec3;

// A vertical triangle in the plane x + y = 2.2, z from 0 up to y / 2.2 (voxel coordinates).
const dvec3 kDiagonal[3] = {{2.2, 0.0, 0.0}, {0.0, 2.2, 0.0}, {0.0, 2.2, 1.0}};

TEST(ConservativeBoxTest, TouchingAClosedFaceMeets) {
  const dvec3 t[3] = {{0.0, 0.0, 1.1}, {1.0, 0.0, 1.1}, {0.0, 1.0, 1.1}};  // 0.1 above the unit box
  EXPECT_FALSE(triangle_meets_box(t, dvec3(0.0), dvec3(1.0)));
  EXPECT_FALSE(triangle_meets_box(t, dvec3(-0.09), dvec3(1.09)));
  EXPECT_TRUE(triangle_meets_box(t, dvec3(-0.1), dvec3(1.1)));  // closed: touching counts
}

TEST(ConservativeBoxTest, DiagonalPlaneNeedsTheLInfinityGrowthNotTheEuclideanDistance) {
  // Voxel (0,0,0): max x + y over [0,1]^2 is 2, so the plane is 0.2/sqrt(2) = 0.141 away, but the
  // box grown by g reaches x + y = 2 + 2g: it meets at g = 0.1, at (1.1, 1.1, z) with z in [0, 0.5].
  EXPECT_TRUE(triangle_meets_box(kDiagonal, dvec3(1.0, 1.0, 0.0), dvec3(2.0, 2.0, 1.0)));
  EXPECT_FALSE(triangle_meets_box(kDiagonal, dvec3(0.0), dvec3(1.0)));
  EXPECT_FALSE(triangle_meets_box(kDiagonal, dvec3(-0.099), dvec3(1.099)));
  EXPECT_TRUE(triangle_meets_box(kDiagonal, dvec3(-0.1), dvec3(1.1)));
  // Voxel (1,1,1): in it x >= 1, so y <= 1.2 and z <= 1.2/2.2 = 0.545 < 1: not met. Grown by g,
  // x >= 1 - g gives z <= (1.2 + g)/2.2, which reaches 1 - g at g = 1/3.2 = 0.3125.
  EXPECT_FALSE(triangle_meets_box(kDiagonal, dvec3(1.0, 1.0, 1.0), dvec3(2.0, 2.0, 2.0)));
  const std::vector<VoxelTriangle> tris = {{kDiagonal[0], kDiagonal[1], kDiagonal[2]}};
  EXPECT_FALSE(any_triangle_meets_voxel(tris, {1, 1, 1}, 0.31));
  EXPECT_TRUE(any_triangle_meets_voxel(tris, {1, 1, 1}, 0.32));
  // Shrunk by 0.25: voxel (1,0,0) keeps x + y = 2.2 inside [1.5, 2.5] with z up to 0.75/2.2 =
  // 0.34 >= 0.25 (at y = 0.75); voxel (0,2,0) is met only at x in [0, 0.2], so no longer.
  EXPECT_TRUE(any_triangle_meets_voxel(tris, {1, 0, 0}, -0.25));
  EXPECT_TRUE(any_triangle_meets_voxel(tris, {0, 2, 0}, 0.0));
  EXPECT_FALSE(any_triangle_meets_voxel(tris, {0, 2, 0}, -0.25));
}

// One tilted triangle in an 8^3 grid whose volume is [0, 8]^3 (voxel = world coordinates).
struct OneTriangle {
  Scene scene;
  Volume exact;
  std::vector<VoxelTriangle> tris;
  OneTriangle() {
    scene.volume.origin = vec3(0.0f);
    scene.volume.size = 8.0f;
    scene.volume.overridden = true;
    scene.materials.push_back(Material());
    const vec3 p[3] = {{1.3f, 1.2f, 2.1f}, {6.4f, 2.1f, 3.7f}, {2.6f, 6.3f, 5.2f}};
    for (const vec3& v : p) {
      scene.positions.push_back(v);
      scene.normals.push_back(vec3(0.0f, 0.0f, 1.0f));
      scene.uv0.push_back(vec2(0.0f));
    }
    scene.triangles.push_back(uvec3(0, 1, 2));
    scene.triangle_material.push_back(0);
    exact = voxelize_conservative(scene, 8).occupancy;
    tris = voxel_space_triangles(scene, 8);
  }
  static size_t at(int x, int y, int z) { return (size_t(z) * 8 + size_t(y)) * 8 + size_t(x); }
};

ConservativeBound gs_bound() {
  BackendFacts f;
  f.conservative_mode = "gs";
  return conservative_bound(f, "test");
}

TEST(ConservativeJudgeTest, TheExactSetItselfPasses) {
  const OneTriangle t;
  const StageVerdict v = judge_conservative_occupancy(t.exact, t.exact, t.tris, gs_bound(), 10);
  EXPECT_EQ(v.verdict, Verdict::Pass) << v.note;
  EXPECT_GT(v.extra["occupied_exact"].get<size_t>(), 20u);
}

TEST(ConservativeJudgeTest, OneMissingVoxelFailsAndIsNamed) {
  const OneTriangle t;
  Volume test = t.exact;
  // A voxel the triangle crosses by far more than the bound: the one holding vertex 1.
  const size_t i = OneTriangle::at(6, 2, 3);
  ASSERT_GT(t.exact.data[i], 0.0f);
  test.data[i] = 0.0f;
  const StageVerdict v = judge_conservative_occupancy(t.exact, test, t.tris, gs_bound(), 10);
  EXPECT_EQ(v.verdict, Verdict::Fail);
  ASSERT_EQ(v.worst.size(), 1u);
  EXPECT_EQ(v.worst[0].at, (std::array<int, 3>{6, 2, 3}));
  EXPECT_NE(v.note.find("voxel (6,2,3) missing"), std::string::npos) << v.note;
  EXPECT_EQ(v.extra["missing_beyond"].get<size_t>(), 1u);
  EXPECT_EQ(v.extra["extra_beyond"].get<size_t>(), 0u);
}

TEST(ConservativeJudgeTest, AnExtraVoxelFailsBeyondTheBoundAndPassesWithin) {
  const OneTriangle t;
  // (7,7,0): far from the triangle. Fails under every mode.
  Volume far = t.exact;
  far.data[OneTriangle::at(7, 7, 0)] = 1.0f;
  const StageVerdict f = judge_conservative_occupancy(t.exact, far, t.tris, gs_bound(), 10);
  EXPECT_EQ(f.verdict, Verdict::Fail);
  EXPECT_NE(f.note.find("voxel (7,7,0) extra"), std::string::npos) << f.note;
  EXPECT_EQ(f.extra["extra_beyond"].get<size_t>(), 1u);
  EXPECT_EQ(f.extra["missing_beyond"].get<size_t>(), 0u);
  // A neighbour of the exact set that the triangle misses by less than a hardware mode's bound
  // (snapping 2^-2 px here, a coarse raster) but more than the gs mode's 2^-10: find one.
  BackendFacts hw;
  hw.conservative_mode = "nv";
  hw.conservative_snap_bits = 2;
  const ConservativeBound coarse = conservative_bound(hw, "test");
  EXPECT_DOUBLE_EQ(coarse.over, 0.25 + kConservativeArithmetic);
  int found = -1;
  for (int i = 0; i < 512 && found < 0; ++i) {
    const ivec3 c(i % 8, (i / 8) % 8, i / 64);
    if (t.exact.data[size_t(i)] == 0.0f && any_triangle_meets_voxel(t.tris, c, 0.2) &&
        !any_triangle_meets_voxel(t.tris, c, 0.01))
      found = i;
  }
  ASSERT_GE(found, 0);
  Volume near = t.exact;
  near.data[size_t(found)] = 1.0f;
  EXPECT_EQ(judge_conservative_occupancy(t.exact, near, t.tris, coarse, 10).verdict, Verdict::Warn);
  EXPECT_EQ(judge_conservative_occupancy(t.exact, near, t.tris, gs_bound(), 10).verdict, Verdict::Fail);
}

TEST(ConservativeJudgeTest, WithoutTrianglesMissingStillFailsAndExtrasWarnUnchecked) {
  const OneTriangle t;
  Volume test = t.exact;
  test.data[OneTriangle::at(7, 7, 0)] = 1.0f;
  const StageVerdict extra = judge_conservative_occupancy(t.exact, test, {}, gs_bound(), 10);
  EXPECT_EQ(extra.verdict, Verdict::Warn);
  EXPECT_EQ(extra.extra["unchecked"].get<size_t>(), 1u);
  test.data[OneTriangle::at(6, 2, 3)] = 0.0f;
  EXPECT_EQ(judge_conservative_occupancy(t.exact, test, {}, gs_bound(), 10).verdict, Verdict::Fail);
}

TEST(ConservativeJudgeTest, HardwareBoundComesFromTheSnappingBitsAndDilation) {
  BackendFacts f;
  f.conservative_mode = "nv";
  f.conservative_snap_bits = 8;
  f.conservative_dilation = 0.25;
  const ConservativeBound b = conservative_bound(f, "test");
  EXPECT_DOUBLE_EQ(b.over, 1.0 / 256 + 0.25 + kConservativeArithmetic);
  EXPECT_DOUBLE_EQ(b.under, 1.0 / 256 + kConservativeArithmetic);
  f.conservative_snap_bits = -1;
  EXPECT_THROW(conservative_bound(f, "test"), std::runtime_error);
}

}  // namespace
}  // namespace vct::cmp
