// The committed scenes in scenes/ load with the counts and properties their generator
// (scenes/generate_scenes.py) builds in; regenerate both together.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/gltf_loader.h"

namespace vct {
namespace {

Scene load_committed(const std::string& name) { return load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/" + name); }

float max_edge(const Scene& s) {
  float m = 0.0f;
  for (const uvec3& t : s.triangles) {
    m = std::max({m, glm::length(s.positions[t.x] - s.positions[t.y]), glm::length(s.positions[t.y] - s.positions[t.z]),
                  glm::length(s.positions[t.z] - s.positions[t.x])});
  }
  return m;
}

void expect_clean(const Scene& s) {
  EXPECT_EQ(s.stats.degenerate_triangles_dropped, 0);
  EXPECT_EQ(s.stats.non_triangle_primitives_skipped, 0);
  EXPECT_TRUE(s.stats.warnings.empty()) << s.stats.warnings.front();
  EXPECT_TRUE(s.camera.from_file);
  ASSERT_EQ(s.normals.size(), s.positions.size());
  ASSERT_EQ(s.tangents.size(), s.positions.size());
  ASSERT_EQ(s.uv0.size(), s.positions.size());
  for (size_t v = 0; v < s.positions.size(); ++v) {
    ASSERT_NEAR(glm::length(s.normals[v]), 1.0f, 1e-4f);
    ASSERT_NEAR(glm::dot(vec3(s.tangents[v]), s.normals[v]), 0.0f, 1e-4f);
  }
  // The default volume contains every triangle.
  const vec3 lo = s.volume.to_texture(s.bounds.lo), hi = s.volume.to_texture(s.bounds.hi);
  EXPECT_GT(glm::min(lo.x, glm::min(lo.y, lo.z)), 0.0f);
  EXPECT_LT(glm::max(hi.x, glm::max(hi.y, hi.z)), 1.0f);
}

TEST(Scenes, CornellBoxIsTheBuiltInDefault) {
  const Scene file = load_committed("cornell_box.gltf");
  const Scene builtin = load_scene("");
  EXPECT_EQ(builtin.source, kBuiltinSceneName);
  expect_clean(file);
  EXPECT_EQ(file.triangle_count(), 2382u);
  EXPECT_EQ(builtin.triangle_count(), file.triangle_count());
  EXPECT_EQ(builtin.positions, file.positions);
  ASSERT_EQ(file.materials.size(), 6u);
  int lambertian = 0, emissive = 0, metals = 0;
  for (const Material& m : file.materials) {
    lambertian += m.specular_factor == 0.0f && m.metallic_factor == 0.0f;
    emissive += m.is_emissive();
    metals += m.metallic_factor == 1.0f;
  }
  EXPECT_EQ(lambertian, 4);  // white, red, green walls + the panel
  EXPECT_EQ(emissive, 1);
  EXPECT_EQ(metals, 1);
  ASSERT_EQ(file.lights.size(), 1u);
  EXPECT_NEAR(file.lights[0].direction.y, -1.0f, 1e-6f);
  EXPECT_EQ(file.bounds.lo, vec3(-1, 0, -1));
  EXPECT_EQ(file.bounds.hi, vec3(1, 2, 1));
}

TEST(Scenes, DemoRoomHasTexturesParticlesAndATwoChannelNormalMap) {
  const Scene s = load_committed("demo_room.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 4104u);
  EXPECT_EQ(s.textures.size(), 3u);
  EXPECT_EQ(s.emitters.size(), 2u);
  EXPECT_EQ(s.lights.size(), 1u);
  int two_channel = 0, normal_mapped = 0;
  for (const Material& m : s.materials) {
    two_channel += m.normal_two_channel;
    normal_mapped += m.normal_texture.present();
  }
  EXPECT_EQ(two_channel, 1);
  EXPECT_EQ(normal_mapped, 2);
  for (const Texture& t : s.textures) EXPECT_EQ(t.rgba8.size(), size_t(t.width) * size_t(t.height) * 4);
}

TEST(Scenes, FurnaceSphereFacesItsCentre) {
  const Scene s = load_committed("furnace_sphere.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 3968u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].base_color_factor, vec4(0.5f, 0.5f, 0.5f, 1.0f));
  EXPECT_EQ(s.materials[0].emission(), vec3(1.0f));
  EXPECT_EQ(s.materials[0].specular_factor, 0.0f);
  EXPECT_TRUE(s.lights.empty());
  EXPECT_EQ(s.camera.position, vec3(0.0f));
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    const uvec3 i = s.triangles[t];
    const vec3 g = glm::cross(s.positions[i.y] - s.positions[i.x], s.positions[i.z] - s.positions[i.x]);
    ASSERT_LT(glm::dot(g, s.positions[i.x] + s.positions[i.y] + s.positions[i.z]), 0.0f) << t;  // inward
  }
}

TEST(Scenes, PlaneSpotIsLambertianUnderADownwardSpot) {
  const Scene s = load_committed("plane_spot.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 512u);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  EXPECT_NEAR(glm::length(l.position - vec3(0, 2, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(l.direction - vec3(0, -1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(l.intensity, 10.0f);
  EXPECT_EQ(s.materials[0].specular_factor, 0.0f);
  EXPECT_EQ(s.bounds.lo.y, 0.0f);
  EXPECT_EQ(s.bounds.hi.y, 0.0f);
}

TEST(Scenes, TinyTrianglesAreFarBelowAVoxel) {
  const Scene s = load_committed("tiny_triangles.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 45002u);
  // Two large floor triangles; the rest have edges of 1/150 m (diagonals sqrt(2)/150).
  size_t small = 0;
  for (const uvec3& t : s.triangles) small += glm::length(s.positions[t.x] - s.positions[t.y]) < 0.01f;
  EXPECT_EQ(small, 45000u);
  const float voxel_at_128 = s.volume.size / 128.0f;
  EXPECT_LT(1.0f / 150.0f, voxel_at_128 / 2.0f);       // legs under half a voxel
  EXPECT_LT(std::sqrt(2.0f) / 150.0f, voxel_at_128);  // diagonals under one voxel
  EXPECT_GT(max_edge(s), 2.0f);  // the floor
}

TEST(Scenes, ThinWallIsThinnerThanAVoxel) {
  const Scene s = load_committed("thin_wall.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 24u);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_LT(s.lights[0].position.x, 0.0f);  // lit room at x < 0
  EXPECT_GT(s.camera.position.x, 0.0f);          // camera in the dark room
  EXPECT_LT(0.02f, s.volume.size / 64.0f / 3.0f);  // the 2 cm wall: under a third of a voxel at 64^3
}

TEST(Scenes, SunRoomHasASunAndTwoPointLamps) {
  const Scene s = load_committed("sun_room.gltf");
  expect_clean(s);
  EXPECT_EQ(s.triangle_count(), 428u);
  ASSERT_EQ(s.lights.size(), 3u);
  // The file's order: the sun, then the lamps (the second with range 6).
  EXPECT_EQ(s.lights[0].kind, LightKind::Directional);
  EXPECT_NEAR(glm::dot(s.lights[0].direction, glm::normalize(vec3(-0.15f, -1.0f, 0.08f))), 1.0f, 1e-6f);
  EXPECT_EQ(s.lights[0].intensity, 8.0f);  // lux
  EXPECT_EQ(s.lights[0].range, 0.0f);
  for (size_t i : {1u, 2u}) {
    EXPECT_EQ(s.lights[i].kind, LightKind::Point);
    EXPECT_EQ(s.lights[i].intensity, 4.0f);  // candela
    EXPECT_EQ(s.lights[i].position.y, 1.9f);
  }
  EXPECT_EQ(s.lights[1].range, 0.0f);
  EXPECT_EQ(s.lights[2].range, 6.0f);
}

}  // namespace
}  // namespace vct
