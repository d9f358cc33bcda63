// Solid voxelization and surface thickening (stages/voxel_fill.h) against hand counts: a closed
// box at 16^3 fills exactly the voxels between its wall layers, an open one fills nothing; a plane
// thickened by k voxels gains exactly k layers behind it (opposite its normal) and none in front.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "stages/inject.h"
#include "stages/voxel_fill.h"
#include "test_box_scene.h"

namespace vct {
namespace {

constexpr int kN = 16;

int layer_of(const Scene& s, float world, int axis) {
  vec3 p(0.5f);
  p[axis] = world;
  return std::min(int(std::floor(to_voxel_space(s, kN, p)[axis])), kN - 1);
}

VoxelGrid filled_grid(const Scene& s, bool solid, int k) {
  VctSettings st;
  st.grid = kN;
  st.solid_voxelization = solid;
  st.surface_thickening_voxels = k;
  return inject_and_reduce(s, voxelize_conservative(s, kN), {}, st);
}

float alpha(const VoxelGrid& g, int x, int y, int z) { return g.radiance.rgba(x, y, z).a; }

// The test box's walls face inward (a room); turned inside out they face outward (a solid box).
Scene outward_box() {
  Scene s = test::closed_box(vec3(0.5f), vec3(0.0f));
  for (uvec3& t : s.triangles) std::swap(t.y, t.z);
  for (vec3& n : s.normals) n = -n;
  return s;
}

TEST(VoxelFill, ClosedBoxInteriorIsFilledExactly) {
  const Scene s = outward_box();
  // The walls lie at 0 and 1 on every axis; the conservative voxelizer puts each in one layer
  // (the half-open voxel box holding the plane). The volume is a cube, so the layers are the same
  // on every axis.
  const int lo = layer_of(s, 0.0f, 0), hi = layer_of(s, 1.0f, 0);
  ASSERT_LT(lo + 1, hi) << "the box must leave an interior at 16^3";
  const VoxelGrid plain = filled_grid(s, false, 0), solid = filled_grid(s, true, 0);
  int interior = 0;
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const bool inside = x > lo && x < hi && y > lo && y < hi && z > lo && z < hi;
        const bool wall = !inside && x >= lo && x <= hi && y >= lo && y <= hi && z >= lo && z <= hi &&
                          (x == lo || x == hi || y == lo || y == hi || z == lo || z == hi);
        interior += inside;
        ASSERT_EQ(alpha(plain, x, y, z), wall ? 1.0f : 0.0f) << x << " " << y << " " << z;
        ASSERT_EQ(alpha(solid, x, y, z), wall || inside ? 1.0f : 0.0f) << x << " " << y << " " << z;
        // Interior voxels are opaque and dark: the light stays on the surface layer.
        if (inside) {
          ASSERT_EQ(vec3(solid.radiance.rgba(x, y, z)), vec3(0.0f));
        }
      }
  EXPECT_EQ(interior, (hi - lo - 1) * (hi - lo - 1) * (hi - lo - 1));
}

TEST(VoxelFill, RoomFacingInwardIsNotFilled) {
  // The same six walls facing inward: every ray from inside meets a wall facing back at it.
  const Scene s = test::closed_box(vec3(0.5f), vec3(0.0f));
  EXPECT_EQ(filled_grid(s, true, 0).radiance.data, filled_grid(s, false, 0).radiance.data);
}

TEST(VoxelFill, OpenBoxIsNotFilled) {
  Scene s = outward_box();
  // Drop the ceiling (triangles 2, 3): every column along y now escapes through the top.
  s.triangles.erase(s.triangles.begin() + 2, s.triangles.begin() + 4);
  s.triangle_material.erase(s.triangle_material.begin() + 2, s.triangle_material.begin() + 4);
  const VoxelGrid plain = filled_grid(s, false, 0), solid = filled_grid(s, true, 0);
  EXPECT_EQ(solid.radiance.data, plain.radiance.data);
}

Scene floor_plane(float height) {
  Scene s = test::closed_box(vec3(0.5f), vec3(0.0f));
  s.triangles.resize(2);  // the floor only, normal +y
  s.triangle_material.resize(2);
  s.positions.resize(4);
  s.normals.resize(4);
  s.uv0.resize(4);
  for (vec3& p : s.positions) p.y = height;
  s.volume.origin = vec3(0.0f) - 0.1f;  // keep the closed box's cube: a flat plane has no extent in y
  s.volume.size = 1.2f;
  return s;
}

TEST(VoxelFill, ThickeningAddsExactlyKLayersBehindAPlane) {
  const Scene s = floor_plane(0.52f);  // voxel y = 8.27: inside layer 8, off any boundary
  const int layer = layer_of(s, 0.52f, 1);
  const VoxelGrid plain = filled_grid(s, false, 0);
  int in_plane = 0;
  for (int z = 0; z < kN; ++z)
    for (int x = 0; x < kN; ++x) in_plane += alpha(plain, x, layer, z) == 1.0f;
  ASSERT_GT(in_plane, 0);
  for (int k = 1; k <= kMaxThickening; ++k) {
    const VoxelGrid g = filled_grid(s, false, k);
    for (int y = 0; y < kN; ++y) {
      int count = 0;
      for (int z = 0; z < kN; ++z)
        for (int x = 0; x < kN; ++x) {
          count += alpha(g, x, y, z) == 1.0f;
          // Only where the plane is: each thickened column sits under a plane voxel.
          if (alpha(g, x, y, z) == 1.0f) {
            ASSERT_EQ(alpha(plain, x, layer, z), 1.0f);
          }
        }
      const bool expected = y <= layer && y >= layer - k;  // the plane and k layers below it (-y)
      EXPECT_EQ(count, expected ? in_plane : 0) << "k = " << k << ", layer " << y;
    }
  }
}

TEST(VoxelFill, FacingDirectionFollowsTheWinding) {
  EXPECT_EQ(facing_direction({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 4);  // +z
  EXPECT_EQ(facing_direction({0, 0, 0}, {0, 1, 0}, {1, 0, 0}), 5);  // -z
  EXPECT_EQ(facing_direction({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), 0);  // +x
  EXPECT_EQ(facing_direction({0, 0, 0}, {0, 0, 1}, {1, 0, 0}), 2);  // +y
}

TEST(VoxelFill, DefaultsAddNothing) {
  const Scene s = test::closed_box(vec3(0.5f), vec3(0.0f));
  Volume v(kN, kN, kN, 4);
  EXPECT_EQ(fill_voxels(s, voxelize_conservative(s, kN), VctSettings{}, v), 0);
}

}  // namespace
}  // namespace vct
