// Voxelization: hand-checked voxel sets for one triangle and axis-aligned quads, the GPU rule
// against the conservative set, tiny triangles and holes.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <tuple>

#include "scene/gltf_loader.h"
#include "stage_test_scene.h"
#include "stages/raster.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

using VoxelSet = std::set<std::tuple<int, int, int>>;

// Volume [0, n]^3 so voxel coordinates equal world coordinates.
Scene unit_grid_scene(int n) {
  Scene s;
  test::add_material(s, vec3(0.5f));
  s.volume.origin = vec3(0.0f);
  s.volume.size = float(n);
  s.volume.overridden = true;
  return s;
}

VoxelSet voxels(const Voxelization& v) {
  VoxelSet out;
  for (const VoxelFragment& f : v.fragments) out.insert({f.voxel.x, f.voxel.y, f.voxel.z});
  return out;
}

TEST(Voxelize, OneTriangleHandCheckedSet) {
  Scene s = unit_grid_scene(4);
  test::add_triangle(s, {0.5f, 0.5f, 0.5f}, {2.5f, 0.5f, 0.5f}, {0.5f, 2.5f, 0.5f}, 0);
  // Points x, y >= 0.5, x + y <= 3 in the z = 0 layer: voxel (i, j) is met iff
  // max(i, .5) + max(j, .5) <= 3 (the corner (1,2) touches voxel (1,2), whose box contains it).
  const VoxelSet expected = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  const Voxelization c = voxelize_conservative(s, 4);
  EXPECT_EQ(voxels(c), expected);
  EXPECT_EQ(c.covered, 8);
  EXPECT_EQ(c.fragments.size(), 8u);
  // Fragment at the closest point to the voxel centre: voxel (0,0) centre (.5,.5,.5) is a vertex.
  EXPECT_EQ(c.fragments[0].voxel, ivec3(0, 0, 0));
  EXPECT_EQ(c.fragments[0].position, vec3(0.5f));
  // Voxel (1,1): centre (1.5,1.5) projects inside the triangle (x + y = 3 is the edge): on it.
  for (const VoxelFragment& f : c.fragments)
    if (f.voxel == ivec3(1, 1, 0)) {
      EXPECT_EQ(f.position, vec3(1.5f, 1.5f, 0.5f));
    }
  EXPECT_EQ(*c.occupancy.voxel(2, 1, 0), 1.0f);
  EXPECT_EQ(*c.occupancy.voxel(2, 2, 0), 0.0f);
  // The GPU rule, 1 sample: every candidate pixel centre lies on an edge. (0.5,1.5) is on the
  // left edge x = 0.5 (covered); (0.5,0.5) and (1.5,0.5) are on the bottom edge y = 0.5 (a bottom
  // edge: not covered); (1.5,1.5), (0.5,2.5), (2.5,0.5) on the hypotenuse (a right edge: not).
  const Voxelization g = voxelize_gpu_rule(s, 4, 1);
  EXPECT_EQ(voxels(g), (VoxelSet{{0, 1, 0}}));
  const Volume h = hole_map(c, g);
  float holes = 0.0f;
  for (float x : h.data) holes += x;
  EXPECT_EQ(holes, 7.0f);
}

TEST(Voxelize, AxisAlignedQuadCoversExactlyItsVoxels) {
  Scene s = unit_grid_scene(8);
  // Quad in z = 2.5 spanning [1, 2.75]^2: voxels 1..2 in x and y, layer 2.
  test::add_quad(s, {1, 1, 2.5f}, {2.75f, 1, 2.5f}, {2.75f, 2.75f, 2.5f}, {1, 2.75f, 2.5f}, {0, 0, 1}, 0);
  VoxelSet expected;
  for (int y = 1; y <= 2; ++y)
    for (int x = 1; x <= 2; ++x) expected.insert({x, y, 2});
  EXPECT_EQ(voxels(voxelize_conservative(s, 8)), expected);
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, 1)), expected);
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, 8)), expected);
  // Both triangles of the quad land in each voxel along the diagonal only.
  EXPECT_EQ(voxelize_conservative(s, 8).fragments.size(), 6u);
}

TEST(Voxelize, FacesOnVoxelBoundariesBelongToTheUpperVoxel) {
  Scene s = unit_grid_scene(8);
  // Quad [1,3]^2 in the plane z = 3: points with x = 3 lie in voxel 3 (half-open [3,4)).
  test::add_quad(s, {1, 1, 3}, {3, 1, 3}, {3, 3, 3}, {1, 3, 3}, {0, 0, 1}, 0);
  VoxelSet expected;
  for (int y = 1; y <= 3; ++y)
    for (int x = 1; x <= 3; ++x) expected.insert({x, y, 3});
  EXPECT_EQ(voxels(voxelize_conservative(s, 8)), expected);
  // The GPU rule: pixel centres 1.5, 2.5 inside; depth 3.0 -> floor -> layer 3.
  VoxelSet gpu;
  for (int y = 1; y <= 2; ++y)
    for (int x = 1; x <= 2; ++x) gpu.insert({x, y, 3});
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, 1)), gpu);
}

TEST(Voxelize, ConstantDepthTriangleStaysInOneLayerUnderTheGpuRule) {
  // A wide floor exactly on the boundary y = 32 of a 64^3 grid, with irregular corners so the
  // barycentrics are inexact: every fragment must land in layer 32 (GL interpolates the depth
  // relative to vertex 0; b0*d0 + b1*d1 + b2*d2 in float put some into layer 31).
  Scene s = unit_grid_scene(64);
  test::add_quad(s, {0.37f, 32, 0.91f}, {63.3f, 32, 1.7f}, {62.9f, 32, 63.13f}, {0.71f, 32, 62.4f}, {0, 1, 0}, 0);
  for (int samples : {1, 4, 8}) {
    const Voxelization v = voxelize_gpu_rule(s, 64, samples);
    ASSERT_GT(v.fragments.size(), 3000u);
    for (const VoxelFragment& f : v.fragments) ASSERT_EQ(f.voxel.y, 32) << samples << " samples";
  }
}

TEST(Voxelize, MsaaFragmentUsesTheExtrapolatedPixelCentreDepth) {
  Scene s = unit_grid_scene(8);
  // In pixel (1,1) only the 4x sample (1.375, 1.125) lies in x + y <= 2.625; the centre does not.
  // Plane z = 2.9 + 0.3 (x - 1): the centre's (extrapolated) depth is 3.05 -> layer 3.
  // (Dyadic x, y so snapping to 1/256 pixel is exact.)
  test::add_triangle(s, {1.0f, 1.0f, 2.9f}, {1.625f, 1.0f, 3.0875f}, {1.0f, 1.625f, 2.9f}, 0);
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, 1)), VoxelSet{});
  const Voxelization g = voxelize_gpu_rule(s, 8, 4);
  ASSERT_EQ(voxels(g), (VoxelSet{{1, 1, 3}}));
  EXPECT_NEAR(g.fragments[0].position.x, 1.5f, 1e-5f);  // evaluated at the centre, outside the triangle
  EXPECT_NEAR(g.fragments[0].position.z, 3.05f, 1e-5f);
  EXPECT_EQ(voxels(voxelize_conservative(s, 8)), (VoxelSet{{1, 1, 2}, {1, 1, 3}}));
}

// A driver's GL_SAMPLE_POSITION list (BackendFacts) replaces the assumed pattern. The triangle of
// the test above covers, in pixel (1,1), only points with x + y <= 2.625.
TEST(Voxelize, DriverSamplePositionsReplaceTheStandardPattern) {
  Scene s = unit_grid_scene(8);
  test::add_triangle(s, {1.0f, 1.0f, 2.9f}, {1.625f, 1.0f, 3.0875f}, {1.0f, 1.625f, 2.9f}, 0);
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, standard_sample_positions(4))), voxels(voxelize_gpu_rule(s, 8, 4)));
  // One sample at (0.375, 0.125): 1.375 + 1.125 = 2.5 <= 2.625, covered.
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, std::vector<vec2>{{0.375f, 0.125f}})), (VoxelSet{{1, 1, 3}}));
  // One sample at (0.625, 0.875): 3.5 > 2.625, not covered; the pixel centre pattern neither.
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, std::vector<vec2>{{0.625f, 0.875f}})), VoxelSet{});
  EXPECT_EQ(voxels(voxelize_gpu_rule(s, 8, std::vector<vec2>{{0.5f, 0.5f}})), voxels(voxelize_gpu_rule(s, 8, 1)));
  EXPECT_THROW(voxelize_gpu_rule(s, 8, std::vector<vec2>{}), std::invalid_argument);
}

TEST(Voxelize, DominantAxisTieBreakingFollowsTheSeed) {
  // p = |cross|: strictly largest z -> z; else x if p.x > p.y; else y.
  EXPECT_EQ(dominant_axis({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 2);
  EXPECT_EQ(dominant_axis({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), 0);
  EXPECT_EQ(dominant_axis({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), 1);
  EXPECT_EQ(dominant_axis({0, 0, 0}, {1, 0, -1}, {0, 1, -1}), 1);  // p = (1,1,1): all tied -> y
  EXPECT_EQ(dominant_axis({0, 0, 0}, {0, 1, -1}, {1, 0, 0}), 1);   // p = (0,1,1): z ties y -> y
  EXPECT_EQ(dominant_axis({0, 0, 0}, {0, 1, 0}, {1, 1, 1}), 0);    // p = (1,0,1): z ties x -> x
}

TEST(Voxelize, GpuRuleWithOneSampleLiesInsideTheConservativeSet) {
  Scene s = unit_grid_scene(16);
  uint32_t seed = 7;
  auto rnd = [&] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 60; ++i) {
    const vec3 a(1 + 14 * rnd(), 1 + 14 * rnd(), 1 + 14 * rnd());
    test::add_triangle(s, a, a + vec3(4 * rnd() - 2, 4 * rnd() - 2, 4 * rnd() - 2), a + vec3(4 * rnd() - 2, 4 * rnd() - 2, 4 * rnd() - 2), 0);
  }
  const Voxelization c = voxelize_conservative(s, 16);
  for (int samples : {1, 4, 8}) {
    const Voxelization g = voxelize_gpu_rule(s, 16, samples);
    int outside = 0;
    for (const VoxelFragment& f : g.fragments) outside += *c.occupancy.voxel(f.voxel.x, f.voxel.y, f.voxel.z) == 0.0f;
    if (samples == 1) {
      EXPECT_EQ(outside, 0);  // the centre sample is a point of the triangle
    }
    EXPECT_LE(g.covered, c.covered);
    std::printf("random triangles, %d samples: gpu %lld voxels, conservative %lld, gpu outside %d\n", samples,
                static_cast<long long>(g.covered), static_cast<long long>(c.covered), outside);
  }
}

TEST(Voxelize, TinyTrianglesHaveNoHolesConservativelyButTheOneSampleRuleMissesSome) {
  Scene s = unit_grid_scene(16);
  uint32_t seed = 11;
  auto rnd = [&] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 200; ++i) {
    const vec3 a(1 + 14 * rnd(), 1 + 14 * rnd(), 1 + 14 * rnd());
    test::add_triangle(s, a, a + vec3(0.2f * rnd(), 0.2f * rnd(), 0.05f), a + vec3(-0.1f * rnd(), 0.2f * rnd(), 0.1f), 0);
  }
  const Voxelization c = voxelize_conservative(s, 16);
  // No holes: every vertex's voxel is occupied, and every triangle has a fragment.
  for (const vec3& p : s.positions) EXPECT_EQ(*c.occupancy.voxel(int(p.x), int(p.y), int(p.z)), 1.0f);
  std::set<uint32_t> tris;
  for (const VoxelFragment& f : c.fragments) tris.insert(f.triangle);
  EXPECT_EQ(tris.size(), s.triangles.size());
  const Voxelization g1 = voxelize_gpu_rule(s, 16, 1), g8 = voxelize_gpu_rule(s, 16, 8);
  const Volume h1 = hole_map(c, g1), h8 = hole_map(c, g8);
  float holes1 = 0.0f, holes8 = 0.0f;
  for (size_t i = 0; i < h1.data.size(); ++i) holes1 += h1.data[i], holes8 += h8.data[i];
  EXPECT_GT(holes1, 50.0f);
  EXPECT_LT(holes8, holes1);
  std::printf("tiny triangles: conservative %lld, 1 sample %lld (holes %g), 8 samples %lld (holes %g)\n",
              static_cast<long long>(c.covered), static_cast<long long>(g1.covered), double(holes1),
              static_cast<long long>(g8.covered), double(holes8));
}

TEST(Voxelize, TinyTrianglesSceneFile) {
  Scene s;
  try {
    s = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/tiny_triangles.gltf");
  } catch (const std::exception& e) {
    GTEST_SKIP() << "loader not available: " << e.what();
  }
  const int n = 64;
  const Voxelization c = voxelize_conservative(s, n);
  for (const vec3& p : s.positions) {
    const glm::dvec3 v = to_voxel_space(s, n, p);
    EXPECT_EQ(*c.occupancy.voxel(int(v.x), int(v.y), int(v.z)), 1.0f);
  }
  const Voxelization g = voxelize_gpu_rule(s, n, 1);
  const Volume h = hole_map(c, g);
  float holes = 0.0f;
  for (float x : h.data) holes += x;
  EXPECT_GT(holes, 0.0f);
  std::printf("tiny_triangles.gltf at %d^3: conservative %lld, gpu 1 sample %lld, holes %g\n", n,
              static_cast<long long>(c.covered), static_cast<long long>(g.covered), double(holes));
}

}  // namespace
}  // namespace vct
