// The analytic scenes as glTF files (scenes/*.gltf, written by scenes/generate_scenes.py) through
// the loader and the path tracer: the furnace value and the spot-lit plane's closed form.
// Cross-checks the loader's units and conventions against the in-code tests.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "scene/gltf_loader.h"

namespace vct::pt {
namespace {

std::string scene_path(const char* name) { return std::string(VCT_SOURCE_DIR) + "/scenes/" + name; }

TEST(SceneFiles, FurnaceSphere) {
  const std::string path = scene_path("furnace_sphere.gltf");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const Scene scene = load_gltf_file(path);
  ASSERT_EQ(scene.materials.size(), 1u);
  const float rho = scene.materials[0].base_color_factor.g, le = scene.materials[0].emission().g;
  PtSettings ps;
  ps.width = ps.height = 24;
  ps.max_depth = 200;
  const PathTracer pt(scene, ps);
  Accumulator acc(ps.width, ps.height);
  pt.render(acc, 48);
  const Image m = acc.mean(kFull), v = acc.variance(kFull);
  double sum = 0.0, var = 0.0;
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) {
      sum += double(m.at(x, y, 1));
      var += double(v.at(x, y, 1));
    }
  const double n = double(ps.width) * ps.height, mean = sum / n, sigma = std::sqrt(var) / n;
  const double expected = double(le) / (1.0 - double(rho));
  std::printf("[furnace_sphere.gltf] %.5f expected %.5f (%.2f sigma, sigma %.5f)\n", mean, expected,
              (mean - expected) / sigma, sigma);
  EXPECT_LT(sigma, 0.01 * expected);
  EXPECT_NEAR(mean, expected, 4.0 * sigma);
}

TEST(SceneFiles, PlaneSpotDirectClosedForm) {
  const std::string path = scene_path("plane_spot.gltf");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const Scene scene = load_gltf_file(path);
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& l = scene.lights[0];
  const vec3 albedo(scene.materials[0].base_color_factor);
  const float plane_y = scene.bounds.lo.y;
  ASSERT_NEAR(scene.bounds.hi.y, plane_y, 1e-6f);  // a horizontal plane
  constexpr int kSize = 32;
  PtSettings ps;
  ps.width = ps.height = kSize;
  const PathTracer pt(scene, ps);
  Accumulator acc(kSize, kSize);
  pt.render(acc, 1);
  const Image direct = acc.mean(kDirect);
  const Camera& c = scene.camera;
  float peak = 0.0f;
  for (float v : direct.data) peak = std::max(peak, v);
  ASSERT_GT(peak, 0.0f);
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const vec3 win(float(x) + 0.5f, float(kSize - y) - 0.5f, 0.5f);
      const vec3 q = glm::unProject(win, c.view(), c.projection(1.0f), vec4(0, 0, kSize, kSize));
      const vec3 d = glm::normalize(q - c.position);
      if (d.y >= 0.0f) continue;
      const vec3 p = c.position + d * ((plane_y - c.position.y) / d.y);
      if (glm::abs(p.x) > 0.99f * scene.bounds.hi.x || glm::abs(p.z) > 0.99f * scene.bounds.hi.z) continue;
      const vec3 to_p = p - l.position;
      const float dist = glm::length(to_p);
      const float ci = std::cos(l.inner_cone_angle), co = std::cos(l.outer_cone_angle);
      const float t = std::clamp((glm::dot(l.direction, to_p / dist) - co) / (ci - co), 0.0f, 1.0f);
      const float window = l.range > 0.0f ? std::clamp(1.0f - std::pow(dist / l.range, 4.0f), 0.0f, 1.0f) : 1.0f;
      const vec3 e = l.color * l.intensity * t * t * window / (dist * dist) * ((l.position.y - plane_y) / dist);
      const vec3 expected = albedo * kInvPi * e;
      for (int ch = 0; ch < 3; ++ch)
        ASSERT_NEAR(direct.at(x, y, ch), expected[ch], 2e-4f * expected[ch] + 1e-5f * peak) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, kSize * kSize / 2);
}

TEST(SceneFiles, DemoRoomExercisesEveryFeature) {
  // Textures, normal maps, a spot light and fire (no emissive surfaces): every other AOV
  // receives light, nothing is NaN, and the noise-free AOVs have zero variance.
  const std::string path = scene_path("demo_room.gltf");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const Scene scene = load_gltf_file(path);
  ASSERT_FALSE(scene.textures.empty());
  ASSERT_FALSE(scene.emitters.empty());
  PtSettings ps;
  ps.width = 48;
  ps.height = 36;
  const PathTracer pt(scene, ps);
  EXPECT_GT(pt.particles().size(), 0u);
  Accumulator acc(ps.width, ps.height);
  const RayCounts rays = pt.render(acc, 3);
  EXPECT_EQ(rays.nonfinite_samples, 0u);
  bool emissive = false;
  for (const Material& m : scene.materials) emissive = emissive || m.is_emissive();
  for (int a = 0; a < kAovCount; ++a) {
    double sum = 0.0;
    for (float v : acc.mean(Aov(a)).data) sum += double(v);
    if (a == kEmission && !emissive)
      EXPECT_EQ(sum, 0.0);
    else
      EXPECT_GT(sum, 0.0) << kAovNames[a];
  }
  for (Aov a : {kDirect, kEmission, kParticles})
    for (float v : acc.variance(a).data) ASSERT_EQ(v, 0.0f) << kAovNames[a];
}

}  // namespace
}  // namespace vct::pt
