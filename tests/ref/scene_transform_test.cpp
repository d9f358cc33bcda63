// scene/scene_transform.h: the metamorphic checks' transforms are exact on the voxel lattice
// (docs/metamorphic.md): whole-voxel moves and 90-degree turns undo bit for bit, and the voxel
// coordinates of every vertex move by whole voxels or mirror exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/gltf_loader.h"
#include "scene/scene_transform.h"

namespace vct {
namespace {

const Scene& cornell() {
  static const Scene s = load_scene("");  // the built-in Cornell box
  return s;
}

bool is_power_of_two(float v) {
  int e = 0;
  return std::frexp(v, &e) == 0.5f;
}

TEST(SceneTransform, TurnIsARightHandedSignedPermutation) {
  EXPECT_EQ(turn90(vec3(1, 0, 0), 2), vec3(0, 1, 0));  // about z: +x -> +y
  EXPECT_EQ(turn90(vec3(0, 1, 0), 2), vec3(-1, 0, 0));
  EXPECT_EQ(turn90(vec3(0, 1, 0), 0), vec3(0, 0, 1));  // about x: +y -> +z
  EXPECT_EQ(turn90(vec3(0, 0, 1), 1), vec3(1, 0, 0));  // about y: +z -> +x
  const vec3 v(0.3f, -1.7f, 2.5f);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(unturn90(turn90(v, a), a), v);
    EXPECT_EQ(turn90(turn90(turn90(turn90(v, a), a), a), a), v);
    // A proper rotation: the cross product turns with the vectors.
    const vec3 x(1.0f, 2.0f, 3.0f), y(-2.0f, 0.5f, 4.0f);
    EXPECT_EQ(glm::cross(turn90(x, a), turn90(y, a)), turn90(glm::cross(x, y), a));
  }
}

TEST(SceneTransform, LatticeVolumeIsDyadicAndHoldsTheSceneWithRoom) {
  const int grid = 32, room = 8;
  const Scene s = on_voxel_lattice(cornell(), grid, room);
  const float voxel = s.volume.size / float(grid);
  EXPECT_TRUE(is_power_of_two(s.volume.size)) << s.volume.size;
  EXPECT_TRUE(s.volume.overridden);
  const float q = voxel / kLatticeStepsPerVoxel;
  // 1/2, 1/4, 1/8 of a lattice step below the voxel lattice: no lattice position on a voxel face.
  const vec3 offset = vec3(0.5f, 0.25f, 0.125f) * q;
  for (int a = 0; a < 3; ++a)
    EXPECT_EQ(std::fmod(s.volume.origin[a] + offset[a], voxel), 0.0f) << a;
  for (const vec3& p : s.positions)
    for (int a = 0; a < 3; ++a) EXPECT_NE(std::fmod(p[a] - s.volume.origin[a], voxel), 0.0f);
  for (const vec3& p : s.positions) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(std::fmod(p[a], q), 0.0f);          // on the lattice
      EXPECT_GE(p[a], s.volume.origin[a] + voxel);  // one free voxel below
      EXPECT_LE(p[a] + float(room + 1) * voxel,
                s.volume.origin[a] + s.volume.size);  // room + one above
    }
  }
  // The snap moves a vertex by at most half a lattice step.
  for (size_t i = 0; i < s.positions.size(); ++i)
    for (int a = 0; a < 3; ++a)
      EXPECT_LE(std::abs(s.positions[i][a] - cornell().positions[i][a]), 0.5f * q);
}

TEST(SceneTransform, WholeVoxelMovesAreExact) {
  const int grid = 32;
  const Scene s = on_voxel_lattice(cornell(), grid, 8);
  const float voxel = s.volume.size / float(grid);
  const vec3 t = vec3(3.0f, -2.0f, 5.0f) * voxel;
  const Scene moved = translated(s, t, true);
  const Scene back = translated(moved, -t, true);
  ASSERT_EQ(back.positions.size(), s.positions.size());
  for (size_t i = 0; i < s.positions.size(); ++i) {
    EXPECT_EQ(back.positions[i], s.positions[i]);
    // The voxel coordinate does not move at all when the volume moves along.
    EXPECT_EQ(moved.volume.to_texture(moved.positions[i]), s.volume.to_texture(s.positions[i]));
  }
  EXPECT_EQ(back.camera.position, s.camera.position);
  EXPECT_EQ(moved.volume.origin, s.volume.origin + t);
  // Inside a fixed volume the voxel coordinate moves by exactly k voxels.
  const Scene shifted = translated(s, vec3(8.0f * voxel), false);
  for (size_t i = 0; i < s.positions.size(); ++i)
    EXPECT_EQ(shifted.volume.to_texture(shifted.positions[i]) * float(grid),
              s.volume.to_texture(s.positions[i]) * float(grid) + vec3(8.0f));
}

TEST(SceneTransform, TurnsMirrorVoxelCoordinatesExactly) {
  const Scene s = on_voxel_lattice(cornell(), 32, 8);
  for (int a = 0; a < 3; ++a) {
    const Scene t = turned90(s, a);
    EXPECT_EQ(t.volume.size, s.volume.size);
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (size_t i = 0; i < s.positions.size(); ++i) {
      const vec3 u = s.volume.to_texture(s.positions[i]), v = t.volume.to_texture(t.positions[i]);
      EXPECT_EQ(v[a], u[a]);
      EXPECT_EQ(v[c], u[b]);
      EXPECT_EQ(v[b], 1.0f - u[c]);  // e_c -> -e_b: mirrored in the cube
      EXPECT_EQ(t.normals[i], turn90(s.normals[i], a));
    }
    EXPECT_EQ(t.camera.forward, turn90(s.camera.forward, a));
    ASSERT_EQ(t.lights.size(), s.lights.size());
    for (size_t l = 0; l < s.lights.size(); ++l)
      EXPECT_EQ(t.lights[l].direction, turn90(s.lights[l].direction, a));
    // Four turns give the scene back bit for bit.
    const Scene four = turned90(turned90(turned90(t, a), a), a);
    for (size_t i = 0; i < s.positions.size(); ++i) EXPECT_EQ(four.positions[i], s.positions[i]);
    EXPECT_EQ(four.volume.origin, s.volume.origin);
  }
}

TEST(SceneTransform, LightScalingDoublesEverySourceAndNothingElse) {
  Scene s = cornell();
  ParticleEmitter e;
  s.emitters.push_back(e);
  const Scene d = light_scaled(s, 2.0f);
  ASSERT_FALSE(s.lights.empty());
  for (size_t i = 0; i < s.materials.size(); ++i) {
    EXPECT_EQ(d.materials[i].emission(), 2.0f * s.materials[i].emission());
    EXPECT_EQ(d.materials[i].base_color_factor, s.materials[i].base_color_factor);
  }
  for (size_t i = 0; i < s.lights.size(); ++i)
    EXPECT_EQ(d.lights[i].intensity, 2.0f * s.lights[i].intensity);
  EXPECT_EQ(d.emitters[0].color_start, 2.0f * e.color_start);
  EXPECT_EQ(d.emitters[0].color_end, 2.0f * e.color_end);
  EXPECT_EQ(d.positions, s.positions);
}

}  // namespace
}  // namespace vct
