// A plane under a spot light, both light models: pt_direct at each pixel centre against the
// closed form written out here (not through vct_shared's spot_irradiance), including a blocker
// whose shadow is computed by an independent ray-quad test. With pixel-centre primary rays and a
// delta light, pt_direct is noise-free, so the tolerance is float rounding.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "shared/vct_shared.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

constexpr int kSize = 40;

struct Setup {
  Scene scene;
  Light light;
  vec3 blocker_corner{-0.9f, 1.2f, -0.5f}, blocker_u{0.5f, 0.0f, 0.0f}, blocker_v{0.0f, 0.0f, 0.4f};
};

Setup make_setup(const Material& floor) {
  Setup s;
  const uint32_t m = test::add_material(s.scene, floor);
  test::add_quad(s.scene, vec3(-10, 0, -10), vec3(0, 0, 20), vec3(20, 0, 0), m);  // y = 0, facing +y
  const uint32_t b = test::add_material(s.scene, test::lambertian(vec3(0.0f)));
  test::add_quad(s.scene, s.blocker_corner, s.blocker_v, s.blocker_u, b);  // facing +y; black
  s.light.position = vec3(0.3f, 2.0f, -0.2f);
  s.light.direction = glm::normalize(vec3(-0.1f, -1.0f, 0.05f));
  s.light.color = vec3(1.0f, 0.8f, 0.6f);
  s.light.intensity = 5.0f;
  s.light.inner_cone_angle = 0.35f;
  s.light.outer_cone_angle = 0.6f;
  s.light.range = 6.0f;
  s.scene.lights.push_back(s.light);
  s.scene.camera = test::look_at(vec3(0.0f, 3.0f, 0.0f), vec3(0.0f), vec3(0, 0, -1), 1.1f);
  test::finish(s.scene);
  return s;
}

/// Pixel centre -> point on y = 0, by unprojecting window coordinates with GLM (an independent
/// route from camera_ray's basis arithmetic).
std::optional<vec3> floor_point(const Camera& c, int x, int y) {
  const mat4 view = c.view(), proj = c.projection(1.0f);
  const vec4 viewport(0, 0, kSize, kSize);
  const vec3 win(float(x) + 0.5f, float(kSize - y) - 0.5f, 0.5f);  // GL windows: row 0 at the bottom
  const vec3 p = glm::unProject(win, view, proj, viewport);
  const vec3 d = glm::normalize(p - c.position);
  if (d.y >= 0.0f) return std::nullopt;
  return c.position + d * (-c.position.y / d.y);
}

/// Does the segment p -> q cross the blocker quad? 1 = yes, 0 = no, -1 = too close to its edge
/// (a margin in the quad's parameters) to call.
int crosses_blocker(const Setup& s, const vec3& p, const vec3& q) {
  const vec3 d = q - p;
  const float t = (s.blocker_corner.y - p.y) / d.y;
  if (!(t > 0.0f && t < 1.0f)) return 0;
  const vec3 h = p + t * d - s.blocker_corner;
  const float a = h.x / s.blocker_u.x, b = h.z / s.blocker_v.z;
  const float margin = 0.02f;
  if (a > margin && a < 1 - margin && b > margin && b < 1 - margin) return 1;
  if (a < -margin || a > 1 + margin || b < -margin || b > 1 + margin) return 0;
  return -1;
}

vec3 expected_irradiance(const Light& l, LightModel model, const vec3& p) {
  const vec3 to_p = p - l.position;
  const float d = glm::length(to_p);
  const float cos_axis = glm::dot(l.direction, to_p / d);
  const float ci = std::cos(l.inner_cone_angle), co = std::cos(l.outer_cone_angle);
  const float cos_incidence = l.position.y > p.y ? (l.position.y - p.y) / d : 0.0f;
  if (model == LightModel::Seed) {
    const float t = std::clamp((cos_axis - co) / (ci - co), 0.0f, 1.0f);
    return l.color * l.intensity * (t * t * (3 - 2 * t)) / (1 + d) * cos_incidence;
  }
  const float t = std::clamp((cos_axis - co) / (ci - co), 0.0f, 1.0f);
  const float r = d / l.range;
  const float window = std::clamp(1 - r * r * r * r, 0.0f, 1.0f);
  return l.color * l.intensity * t * t * window / (d * d) * cos_incidence;
}

void check_plane(const Material& floor, LightModel model, bool lambert_closed_form) {
  const Setup s = make_setup(floor);
  PtSettings ps;
  ps.width = ps.height = kSize;
  ps.light_model = model;
  ps.max_depth = 4;
  const PathTracer pt(s.scene, ps);
  Accumulator acc(kSize, kSize);
  pt.render(acc, 2);
  const Image direct = acc.mean(kDirect), var = acc.variance(kDirect);
  // Tolerance: float rounding of the cone ramp near its edge scales with the peak value.
  float peak = 0.0f;
  for (float v : direct.data) peak = std::max(peak, v);
  int lit = 0, shadowed = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::optional<vec3> p = floor_point(s.scene.camera, x, y);
      ASSERT_TRUE(p.has_value());
      // The camera may see the (black) blocker instead of the floor: then direct is 0.
      const int seen = crosses_blocker(s, s.scene.camera.position, *p);
      const int state = seen == 0 ? crosses_blocker(s, *p, s.light.position) : (seen > 0 ? 1 : -1);
      if (state < 0) continue;
      const vec3 e = state == 1 ? vec3(0.0f) : expected_irradiance(s.light, model, *p);
      vec3 expected;
      if (lambert_closed_form) {
        expected = vec3(floor.base_color_factor) * kInvPi * e;
      } else {
        const sh::SurfacePbr pbr = sh::surface_pbr(vec3(floor.base_color_factor), floor.metallic_factor,
                                                   floor.roughness_factor, 1.0f, vec3(1.0f));
        const vec3 n(0, 1, 0), v = glm::normalize(s.scene.camera.position - *p),
                   l = glm::normalize(s.light.position - *p);
        expected = sh::cook_torrance(pbr, n, v, l) * e;
      }
      const vec3 got = direct.rgb(x, y);
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(got[c], expected[c], 2e-4f * expected[c] + 1e-5f * peak)
            << "pixel " << x << "," << y << " p " << p->x << " " << p->z << " state " << state;
        ASSERT_EQ(var.at(x, y, c), 0.0f);
      }
      (state == 1 ? shadowed : lit) += expected != vec3(0.0f) || state == 1;
    }
  // The scene must exercise the cone, the shadow and the falloff.
  EXPECT_GT(lit, 200);
  EXPECT_GT(shadowed, 20);
}

TEST(SpotPlane, LambertGltfModel) { check_plane(test::lambertian(vec3(0.7f, 0.5f, 0.3f)), LightModel::Gltf, true); }
TEST(SpotPlane, LambertSeedModel) { check_plane(test::lambertian(vec3(0.7f, 0.5f, 0.3f)), LightModel::Seed, true); }
TEST(SpotPlane, GlossyGltfModel) { check_plane(test::pbr(vec3(0.9f, 0.6f, 0.2f), 0.3f, 0.4f), LightModel::Gltf, false); }

TEST(SpotPlane, AlonePlaneHasNoIndirectLight) {
  // Without the blocker nothing bounces back: full == direct, both indirect AOVs are zero.
  Scene scene;
  const uint32_t m = test::add_material(scene, test::lambertian(vec3(0.8f)));
  test::add_quad(scene, vec3(-10, 0, -10), vec3(0, 0, 20), vec3(20, 0, 0), m);
  Light l;
  l.position = vec3(0, 2, 0);
  l.direction = vec3(0, -1, 0);
  l.intensity = 3.0f;
  scene.lights.push_back(l);
  scene.camera = test::look_at(vec3(0.5f, 3.0f, 0.5f), vec3(0.0f), vec3(0, 0, -1), 1.0f);
  test::finish(scene);
  PtSettings ps;
  ps.width = ps.height = 16;
  const PathTracer pt(scene, ps);
  Accumulator acc(16, 16);
  pt.render(acc, 4);
  const Image full = acc.mean(kFull), direct = acc.mean(kDirect);
  EXPECT_EQ(full.data, direct.data);
  for (float v : acc.mean(kIndirectDiffuse).data) EXPECT_EQ(v, 0.0f);
  for (float v : acc.mean(kIndirectSpecular).data) EXPECT_EQ(v, 0.0f);
  float peak = 0.0f;
  for (float v : direct.data) peak = std::max(peak, v);
  EXPECT_GT(peak, 0.1f);
}

}  // namespace
}  // namespace vct::pt
