// The path tracer's next-event estimation for point and directional lights against closed forms
// written out here: a point light over a plane, E = I cos(theta) / d^2 x the glTF range window,
// with a blocker whose shadow an independent ray-quad test decides; a sun on a tilted plane, E =
// lux cos(theta) everywhere. Pixel-centre primary rays and delta lights make pt_direct noise-free,
// so the tolerance is float rounding.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "scene/exposure.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

constexpr int kSize = 32;
const vec3 kAlbedo(0.7f, 0.5f, 0.3f);

Image render_direct(const Scene& scene, Image* variance) {
  PtSettings ps;
  ps.width = ps.height = kSize;
  ps.max_depth = 3;
  const PathTracer pt(scene, ps);
  Accumulator acc(kSize, kSize);
  pt.render(acc, 2);
  *variance = acc.variance(kDirect);
  return acc.mean(kDirect);
}

// Pixel centre -> the camera ray (GLM unprojection, independent of camera_ray's basis arithmetic),
// through the far plane: a point near the camera would leave the direction ~1e-5 off, which the
// range window (steep near its end) turns into ~1e-3 relative.
vec3 pixel_ray(const Camera& c, int x, int y) {
  const vec4 viewport(0, 0, kSize, kSize);
  const vec3 win(float(x) + 0.5f, float(kSize - y) - 0.5f,
                 1.0f);  // GL windows: row 0 at the bottom
  return glm::normalize(glm::unProject(win, c.view(), c.projection(1.0f), viewport) - c.position);
}

TEST(LightKindsPlane, PointLightIsInverseSquareWithRangeAndShadow) {
  Scene scene;
  const uint32_t m = test::add_material(scene, test::lambertian(kAlbedo));
  test::add_quad(scene, vec3(-10, 0, -10), vec3(0, 0, 20), vec3(20, 0, 0), m);  // y = 0, facing +y
  const uint32_t black = test::add_material(scene, test::lambertian(vec3(0.0f)));
  const vec3 bc(0.2f, 1.0f, -0.3f), bu(0.4f, 0, 0), bv(0, 0, 0.3f);  // blocker at y = 1
  test::add_quad(scene, bc, bv, bu, black);
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.1f, 1.8f, 0.0f);
  l.color = vec3(1.0f, 0.9f, 0.7f);
  l.intensity = 6.0f;
  l.range = 3.0f;
  scene.lights.push_back(l);
  scene.camera = test::look_at(vec3(0.0f, 4.0f, 0.0f), vec3(0.0f), vec3(0, 0, -1), 1.2f);
  test::finish(scene);
  Image var;
  const Image direct = render_direct(scene, &var);
  int lit = 0, shadowed = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const vec3 d = pixel_ray(scene.camera, x, y);
      const vec3 p = scene.camera.position + d * (-scene.camera.position.y / d.y);
      // Blocker crossings (camera -> p, p -> light) at y = 1, with a margin around its edges.
      auto crossing = [&](const vec3& a, const vec3& b) {
        const float t = (bc.y - a.y) / (b.y - a.y);
        if (!(t > 0.0f && t < 1.0f)) return 0;
        const vec3 h = a + t * (b - a) - bc;
        const float u = h.x / bu.x, v = h.z / bv.z, e = 0.03f;
        if (u > e && u < 1 - e && v > e && v < 1 - e) return 1;
        return (u < -e || u > 1 + e || v < -e || v > 1 + e) ? 0 : -1;
      };
      const int seen = crossing(scene.camera.position, p);
      if (seen != 0) continue;  // the black blocker, or too close to its edge to call
      const int blocked = crossing(p, l.position);
      if (blocked < 0) continue;
      const float dist = glm::length(l.position - p), cos_t = (l.position.y - p.y) / dist;
      const float window = std::max(std::min(1.0f - std::pow(dist / l.range, 4.0f), 1.0f), 0.0f);
      const vec3 expected =
          blocked ? vec3(0.0f)
                  : kAlbedo / kPi * l.color * l.intensity * cos_t / (dist * dist) * window;
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(direct.at(x, y, c), expected[c], 2e-4f * expected[c] + 1e-6f) << x << "," << y;
        ASSERT_EQ(var.at(x, y, c), 0.0f);
      }
      (blocked ? shadowed : lit) += 1;
    }
  EXPECT_GT(lit, 400);
  EXPECT_GT(shadowed, 10);
}

TEST(LightKindsPlane, SunOnATiltedPlaneIsLuxTimesCosine) {
  for (float tilt : {0.0f, 0.6f, 1.2f}) {
    Scene scene;
    const uint32_t m = test::add_material(scene, test::lambertian(kAlbedo));
    // Tilted about z: normal (sin, cos, 0); a large quad through the origin.
    const vec3 u = 20.0f * vec3(std::cos(tilt), -std::sin(tilt), 0.0f), w(0, 0, 20);
    test::add_quad(scene, -0.5f * u - 0.5f * w, w, u, m);
    Light sun;
    sun.kind = LightKind::Directional;
    sun.direction = vec3(0.0f, -1.0f, 0.0f);
    sun.color = vec3(1.0f, 0.95f, 0.8f);
    sun.intensity = 3.0f;  // lux
    scene.lights.push_back(sun);
    const vec3 n(std::sin(tilt), std::cos(tilt), 0.0f);
    scene.camera = test::look_at(3.0f * n, vec3(0.0f), vec3(0, 0, -1), 0.8f);
    test::finish(scene);
    Image var;
    const Image direct = render_direct(scene, &var);
    const vec3 expected = kAlbedo / kPi * sun.color * sun.intensity * std::cos(tilt);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(direct.at(x, y, c), expected[c], 2e-4f * expected[c])
              << tilt << " " << x << "," << y;
          ASSERT_EQ(var.at(x, y, c), 0.0f);
        }
  }
}

// A hard spot (innerConeAngle == outerConeAngle) 1.5 m above the floor, its lamp Blender-photometric
// (21740 cd: a 400 W "Standard" export) and auto-exposed: lit strictly inside the outer cone with
// E = I cos / d^2 x 2^stops, dark outside (docs/scenes.md, "Hard spots" and "Light units and exposure").
TEST(LightKindsPlane, PreExposedHardSpotIsAStepWithTheClosedFormInside) {
  Scene scene;
  const uint32_t m = test::add_material(scene, test::lambertian(kAlbedo));
  test::add_quad(scene, vec3(-10, 0, -10), vec3(0, 0, 20), vec3(20, 0, 0), m);
  Light l;
  l.kind = LightKind::Spot;
  l.position = vec3(0.0f, 1.5f, 0.0f);
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.intensity = 21740.6f;
  l.inner_cone_angle = l.outer_cone_angle = 0.35f;
  scene.lights.push_back(l);
  scene.camera = test::look_at(vec3(0.0f, 4.0f, 0.0f), vec3(0.0f), vec3(0, 0, -1), 0.6f);
  test::finish(scene);
  pre_expose(scene, resolve_exposure(scene, ExposureMode::Auto, 0.0f));
  ASSERT_LT(scene.exposure.stops, -4);
  Image var;
  const Image direct = render_direct(scene, &var);
  const float cos_outer = std::cos(l.outer_cone_angle);
  int lit = 0, dark = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const vec3 d = pixel_ray(scene.camera, x, y);
      const vec3 p = scene.camera.position + d * (-scene.camera.position.y / d.y);
      const float dist = glm::length(l.position - p), cos_t = (l.position.y - p.y) / dist;
      if (std::abs(cos_t - cos_outer) < 1e-5f) continue;  // the tie band (docs/compare.md, "Hard spots")
      const bool inside = cos_t > cos_outer;
      const vec3 expected = inside ? kAlbedo / kPi * l.intensity * scene.exposure.scale * cos_t / (dist * dist) : vec3(0.0f);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(direct.at(x, y, c), expected[c], 2e-4f * expected[c] + 1e-6f) << x << "," << y;
      (inside ? lit : dark) += 1;
    }
  EXPECT_GT(lit, 100);
  EXPECT_GT(dark, 100);
}

}  // namespace
}  // namespace vct::pt
