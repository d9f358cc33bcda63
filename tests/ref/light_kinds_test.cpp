// Point and directional lights in the CPU reference against closed forms written out here (not
// through vct_shared.h): a point light over a plane, E = I cos(theta) / d^2 (times the glTF range
// window), and a sun on a tilted plane, E = lux cos(theta), through the G-buffer, the shadow maps
// (a cube for the point light, an orthographic map for the sun) and image.direct; plus their
// shadows, and a scene with one light of each kind.
#include <gtest/gtest.h>

#include <cmath>

#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

constexpr float kAlbedo = 0.5f, kHeight = 1.0f;

uint32_t lambert_material(Scene& s) {
  const uint32_t m = test::add_material(s, vec3(kAlbedo));
  s.materials[m].specular_factor = 0.0f;  // F = 0: a pure Lambertian surface
  return m;
}

Light point_light(float intensity, float range) {
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f, kHeight, 0.0f);
  l.color = vec3(1.0f, 0.5f, 0.25f);
  l.intensity = intensity;
  l.range = range;
  return l;
}

// The floor y = 0 under a point light at height 1; optionally a small occluder at height 0.5.
Scene point_plane(float range, bool occluder) {
  Scene s;
  const uint32_t m = lambert_material(s);
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  if (occluder)
    test::add_quad(s, {0.3f, 0.5f, -0.1f}, {0.5f, 0.5f, -0.1f}, {0.5f, 0.5f, 0.1f},
                   {0.3f, 0.5f, 0.1f}, {0, 1, 0}, m);
  s.lights.push_back(point_light(3.0f, range));
  s.volume = fit_volume(s.bounds);
  test::top_camera(s);
  return s;
}

// Closed form: L = albedo/pi * I * cos / d^2 * max(min(1 - (d/range)^4, 1), 0).
vec3 point_closed_form(const Light& l, const vec3& p) {
  const float d = glm::length(l.position - p), cos_t = (l.position.y - p.y) / d;
  float window = 1.0f;
  if (l.range > 0.0f) window = std::max(std::min(1.0f - std::pow(d / l.range, 4.0f), 1.0f), 0.0f);
  return kAlbedo / kPi * l.color * l.intensity * cos_t / (d * d) * window;
}

TEST(LightKinds, PointLightOverAPlaneIsInverseSquareInImageDirect) {
  for (float range : {0.0f, 2.0f}) {
    const Scene s = point_plane(range, false);
    VctSettings st;
    st.width = st.height = 48;
    st.shadow_map_size = 256;
    const auto maps = render_shadow_maps(s, st);
    ASSERT_TRUE(maps[0].is_cube());
    const GBuffer g = render_gbuffer(s, st);
    const Image img = shade_direct(s, g, maps, st);
    int checked = 0;
    for (int y = 0; y < st.height; ++y)
      for (int x = 0; x < st.width; ++x) {
        if (g.coverage.at(x, y, 0) == 0.0f) continue;
        const vec3 p = g.position.rgb(x, y);
        // The -y face sees the whole floor at one depth (no PCF acne): keep its taps on it.
        if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;
        const vec3 expected = point_closed_form(s.lights[0], p);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(img.at(x, y, c), expected[c], 1e-6f + 1e-5f * expected[c]) << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 600);
  }
}

TEST(LightKinds, PointLightCubeShadowsTheFloorBehindAnOccluder) {
  const Scene s = point_plane(0.0f, true);
  VctSettings st;
  st.width = st.height = 48;
  st.shadow_map_size = 256;
  const auto maps = render_shadow_maps(s, st);
  const GBuffer g = render_gbuffer(s, st);
  const Image img = shade_direct(s, g, maps, st);
  int shadowed = 0;
  for (int y = 0; y < st.height; ++y)
    for (int x = 0; x < st.width; ++x) {
      if (g.coverage.at(x, y, 0) == 0.0f) continue;
      const vec3 p = g.position.rgb(x, y);
      if (std::abs(p.y) > 1e-4f) continue;
      // The occluder (x 0.3..0.5, |z| < 0.1 at height 0.5) shadows x 0.6..1.0, |z| < 0.2; inside
      // it:
      if (p.x > 0.68f && p.x < 0.92f && std::abs(p.z) < 0.12f) {
        EXPECT_EQ(img.at(x, y, 0), 0.0f) << p.x << " " << p.z;
        ++shadowed;
      }
    }
  EXPECT_GT(shadowed, 4);
}

// A plane through the origin tilted by `tilt` about z (normal (sin, cos, 0)) under a sun shining
// straight down, optionally with a small occluder above it.
Scene sun_plane(float tilt, bool occluder) {
  Scene s;
  const uint32_t m = lambert_material(s);
  const vec3 n(std::sin(tilt), std::cos(tilt), 0.0f), u(std::cos(tilt), -std::sin(tilt), 0.0f),
      w(0, 0, 1);
  test::add_quad(s, -2.0f * u - 2.0f * w, 2.0f * u - 2.0f * w, 2.0f * u + 2.0f * w,
                 -2.0f * u + 2.0f * w, n, m);
  if (occluder)
    test::add_quad(s, {-0.1f, 1.0f, -0.1f}, {0.1f, 1.0f, -0.1f}, {0.1f, 1.0f, 0.1f},
                   {-0.1f, 1.0f, 0.1f}, {0, 1, 0}, m);
  Light l;
  l.kind = LightKind::Directional;
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.color = vec3(0.9f, 1.0f, 0.8f);
  l.intensity = 2.0f;         // lux
  l.position = vec3(100.0f);  // a sun's position means nothing
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  test::top_camera(s);
  return s;
}

TEST(LightKinds, SunOnATiltedPlaneIsLuxTimesCosineInImageDirect) {
  for (float tilt : {0.0f, 0.5f, 1.0f}) {
    const Scene s = sun_plane(tilt, false);
    VctSettings st;
    st.width = st.height = 48;
    st.shadow_map_size = 256;
    // A constant bias must exceed the plane's depth change over the PCF footprint (tan(tilt) x
    // 1.5 texels of a ~4.3 wide map, over a ~4.3 deep depth range: 0.009 at tilt 1) or the
    // tilted plane shadows itself (acne, as under a spot): 0.02 here.
    st.shadow_bias = 0.02f;
    const auto maps = render_shadow_maps(s, st);
    ASSERT_FALSE(maps[0].depth.empty());
    const GBuffer g = render_gbuffer(s, st);
    const Image img = shade_direct(s, g, maps, st);
    const vec3 expected =
        kAlbedo / kPi * s.lights[0].color * s.lights[0].intensity * std::cos(tilt);
    int checked = 0;
    for (int y = 0; y < st.height; ++y)
      for (int x = 0; x < st.width; ++x) {
        if (g.coverage.at(x, y, 0) == 0.0f) continue;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(img.at(x, y, c), expected[c], 1e-5f * expected[c]) << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 1000) << tilt;
  }
}

TEST(LightKinds, SunMapCoversTheVolumeAndCastsAParallelShadow) {
  Scene s = sun_plane(0.0f, true);
  // Slanted by 0.5 in x per unit of height: the occluder at height 1 (|x|, |z| < 0.1, hiding
  // |x| < 0.15 of the floor from the camera above) shadows x in [0.4, 0.6], |z| < 0.1.
  s.lights[0].direction = glm::normalize(vec3(0.5f, -1.0f, 0.0f));
  VctSettings st;
  st.width = st.height = 48;
  st.shadow_map_size = 256;
  st.shadow_bias = 0.02f;  // above the floor's depth change over the PCF footprint at this slant
  const auto maps = render_shadow_maps(s, st);
  // Every corner of the volume lands inside the map (NDC within [-1, 1] on all axes).
  for (int c = 0; c < 8; ++c) {
    const vec3 corner =
        s.volume.to_world(vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)));
    const vec4 clip = maps[0].view_proj * vec4(corner, 1.0f);
    EXPECT_FLOAT_EQ(clip.w, 1.0f);
    for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(clip[a]), 1.0f + 1e-5f) << c << " " << a;
  }
  const GBuffer g = render_gbuffer(s, st);
  const Image img = shade_direct(s, g, maps, st);
  int shadowed = 0;
  for (int y = 0; y < st.height; ++y)
    for (int x = 0; x < st.width; ++x) {
      if (g.coverage.at(x, y, 0) == 0.0f) continue;
      const vec3 p = g.position.rgb(x, y);
      if (std::abs(p.y) > 1e-4f) continue;
      if (std::abs(p.x - 0.5f) < 0.06f && std::abs(p.z) < 0.06f) {
        EXPECT_EQ(img.at(x, y, 0), 0.0f) << p.x << " " << p.z;
        ++shadowed;
      }
      if (std::abs(p.x - 0.5f) > 0.2f || std::abs(p.z) > 0.2f) {
        EXPECT_GT(img.at(x, y, 0), 0.0f) << p.x << " " << p.z;
      }
    }
  EXPECT_GT(shadowed, 0);
}

TEST(LightKinds, MixedLightsAddUp) {
  // One spot, one point and one sun: image.direct is the sum of each light alone.
  Scene all = point_plane(0.0f, false);
  Light spot;
  spot.position = vec3(0.5f, 1.5f, 0.0f);
  spot.direction = vec3(0.0f, -1.0f, 0.0f);
  spot.intensity = 4.0f;
  spot.outer_cone_angle = 0.6f;
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(vec3(0.3f, -1.0f, 0.2f));
  sun.intensity = 1.5f;
  all.lights.push_back(spot);
  all.lights.push_back(sun);
  VctSettings st;
  st.width = st.height = 32;
  st.shadow_map_size = 128;
  const GBuffer g = render_gbuffer(all, st);
  const Image sum = shade_direct(all, g, render_shadow_maps(all, st), st);
  Image parts(st.width, st.height, 3, 0.0f);
  for (size_t i = 0; i < all.lights.size(); ++i) {
    Scene one = all;
    one.lights = {all.lights[i]};
    const Image img = shade_direct(one, g, render_shadow_maps(one, st), st);
    for (size_t k = 0; k < img.data.size(); ++k) parts.data[k] += img.data[k];
  }
  float peak = 0.0f;
  for (size_t k = 0; k < sum.data.size(); ++k) {
    EXPECT_NEAR(sum.data[k], parts.data[k], 1e-6f + 1e-6f * parts.data[k]);
    peak = std::max(peak, sum.data[k]);
  }
  EXPECT_GT(peak, 0.1f);
  EXPECT_EQ(shadow_map_layers(all), 8);
}

}  // namespace
}  // namespace vct
