// Point and directional lights on GL against the CPU reference and against closed forms: sun_room
// (a sun, two point lamps) plus a spot, judged stage by stage as `vct validate` judges it (every
// shadow map and cube face, direct light, voxels, mips, cones); and image.direct of a point light
// over a plane (E = I cos / d^2) and of a sun on a tilted plane (E = lux cos) from GL's own
// G-buffer positions (32^3, 64^2).
#include <cmath>
#include <cstdio>

#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "scene/exposure.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

// scenes/sun_room.gltf (a sun and two point lamps, placed clear of the constant bias's acne at
// 1024^2 maps: docs/pipeline.md "Shadow maps") plus a narrow spot straight down onto the floor,
// which faces it head-on: all three kinds in one frame.
Scene mixed_light_room() {
  Scene s = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/sun_room.gltf");
  Light spot;
  spot.name = "spot";
  spot.position = vec3(-0.3f, 3.6f, 0.0f);
  spot.direction = vec3(0.0f, -1.0f, 0.0f);
  spot.intensity = 6.0f;
  spot.inner_cone_angle = 0.2f;
  spot.outer_cone_angle = 0.3f;
  s.lights.push_back(spot);
  return s;
}

TEST(GlLightKinds, MixedLightsPassEveryStage) {
  VCT_REQUIRE_GL();
  const Scene scene = mixed_light_room();
  ASSERT_EQ(scene.lights.size(), 4u);
  Settings s = small_settings();
  s.vct.shadow_map_size = 1024;  // validate's size, which sun_room is placed for
  const FrameResult gl = render_gl_frame(*ctx, scene, s);
  const FrameResult ref = render_ref_frame(scene, s);
  ASSERT_EQ(gl.shadow_maps.size(), 4u);
  EXPECT_FALSE(gl.shadow_maps[0].depth.empty());  // the sun
  EXPECT_TRUE(gl.shadow_maps[1].is_cube());
  EXPECT_TRUE(gl.shadow_maps[2].is_cube());
  EXPECT_FALSE(gl.shadow_maps[3].depth.empty());  // the spot
  for (int f = 0; f < 6; ++f)
    EXPECT_EQ(gl.shadow_maps[1].cube_view_proj[size_t(f)],
              ref.shadow_maps[1].cube_view_proj[size_t(f)]);
  EXPECT_EQ(gl.shadow_maps[0].view_proj, ref.shadow_maps[0].view_proj);
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
  cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s.vct), gl_set);
  cmp::judge_cones_on_test_inputs(rep, scene, gl, s.vct, gl_set);  // as validate does
  int light_stages = 0;
  for (const auto& st : rep.stages) {
    std::printf("  %-24s %-5s %s\n", st.stage.c_str(), to_string(st.verdict).c_str(),
                st.note.c_str());
    if (st.stage.rfind("shadow_map", 0) == 0) {
      ++light_stages;
      EXPECT_NE(st.verdict, cmp::Verdict::Missing) << st.stage;
    }
  }
  EXPECT_EQ(light_stages, 1 + 6 + 6 + 1);  // sun map, two cubes, spot map
  EXPECT_EQ(rep.first_failing(), "") << "failing stages: " << failing_stages(rep);
}

// A floor under a point light or a tilted plane under a sun, seen from above.
Scene plane_scene(const Light& light, float tilt) {
  Scene s;
  Material m;
  m.base_color_factor = vec4(0.5f, 0.5f, 0.5f, 1.0f);
  m.metallic_factor = 0.0f;
  m.specular_factor = 0.0f;  // pure Lambertian
  m.double_sided = true;
  s.materials.push_back(m);
  const vec3 n(std::sin(tilt), std::cos(tilt), 0.0f),
      u = 2.0f * vec3(std::cos(tilt), -std::sin(tilt), 0.0f), w(0, 0, 2);
  const vec3 corners[4] = {-u - w, u - w, u + w, -u + w};
  for (const vec3& p : corners) {
    s.positions.push_back(p);
    s.normals.push_back(n);
    s.uv0.push_back(vec2(0.0f));
    s.bounds.add(p);
  }
  s.triangles = {uvec3(0, 2, 1), uvec3(0, 3, 2)};  // front face toward n (the camera's side)
  s.triangle_material = {0, 0};
  s.lights.push_back(light);
  s.volume = fit_volume(s.bounds);
  s.camera.position = vec3(0.0f, 3.0f, 0.001f);
  s.camera.forward = vec3(0.0f, -1.0f, 0.0f);
  s.camera.up = vec3(0.0f, 0.0f, -1.0f);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
  s.source = "test:plane";
  return s;
}

TEST(GlLightKinds, PointLightOverAPlaneIsInverseSquare) {
  VCT_REQUIRE_GL();
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f, 1.0f, 0.0f);
  l.intensity = 3.0f;
  l.range = 2.0f;
  const Scene scene = plane_scene(l, 0.0f);
  const FrameResult f = render_gl_frame(*ctx, scene, small_settings());
  int checked = 0;
  for (int y = 0; y < f.gbuffer.coverage.height; ++y)
    for (int x = 0; x < f.gbuffer.coverage.width; ++x) {
      if (f.gbuffer.coverage.at(x, y, 0) == 0.0f) continue;
      const vec3 p = f.gbuffer.position.rgb(x, y);
      if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;  // PCF taps stay on the -y face
      const float d = glm::length(l.position - p), cos_t = (l.position.y - p.y) / d;
      const float window = std::max(std::min(1.0f - std::pow(d / l.range, 4.0f), 1.0f), 0.0f);
      const float expected = 0.5f / kPi * l.intensity * cos_t / (d * d) * window;
      EXPECT_NEAR(f.images.direct.at(x, y, 0), expected, 1e-4f * expected + 1e-6f) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

TEST(GlLightKinds, SunOnATiltedPlaneIsLuxTimesCosine) {
  VCT_REQUIRE_GL();
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = vec3(0.0f, -1.0f, 0.0f);
  sun.intensity = 2.0f;
  for (float tilt : {0.0f, 0.8f}) {
    const Scene scene = plane_scene(sun, tilt);
    Settings s = small_settings();
    s.vct.shadow_bias =
        0.02f;  // above the tilted plane's depth change over the PCF footprint (ref test)
    const FrameResult f = render_gl_frame(*ctx, scene, s);
    const float expected = 0.5f / kPi * sun.intensity * std::cos(tilt);
    int checked = 0;
    for (int y = 0; y < f.gbuffer.coverage.height; ++y)
      for (int x = 0; x < f.gbuffer.coverage.width; ++x) {
        if (f.gbuffer.coverage.at(x, y, 0) == 0.0f) continue;
        // The G-buffer normal is the plane's up to float rounding: cos from it moves by ~1e-6.
        EXPECT_NEAR(f.images.direct.at(x, y, 0), expected, 1e-4f * expected)
            << tilt << " " << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 1000);
  }
}

}  // namespace
}  // namespace vct::gl::test

namespace vct::gl::test {
namespace {

// A hard spot (innerConeAngle == outerConeAngle; docs/scenes.md, "Hard spots") straight down from
// 1 m: lit strictly inside the outer cone with E = I cos / d^2, dark outside, in both light models
// (the seed's smoothstep with equal edges would be undefined in GLSL). Pixels whose cos angle lies
// within 1e-5 of the edge may go either way (docs/compare.md, "Hard spots"), and are skipped.
TEST(GlLightKinds, HardSpotIsAStepAtTheOuterCone) {
  VCT_REQUIRE_GL();
  Light l;
  l.kind = LightKind::Spot;
  l.position = vec3(0.0f, 1.0f, 0.0f);
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.intensity = 3.0f;
  l.inner_cone_angle = l.outer_cone_angle = 0.5f;
  const Scene scene = plane_scene(l, 0.0f);
  for (LightModel model : {LightModel::Gltf, LightModel::Seed}) {
    Settings s = small_settings();
    s.vct.light_model = model;
    const FrameResult f = render_gl_frame(*ctx, scene, s);
    int lit = 0, dark = 0;
    for (int y = 0; y < f.gbuffer.coverage.height; ++y)
      for (int x = 0; x < f.gbuffer.coverage.width; ++x) {
        if (f.gbuffer.coverage.at(x, y, 0) == 0.0f) continue;
        const vec3 p = f.gbuffer.position.rgb(x, y);
        const float d = glm::length(l.position - p), cos_t = (l.position.y - p.y) / d;
        if (std::abs(cos_t - std::cos(l.outer_cone_angle)) < 1e-5f) continue;
        const bool inside = cos_t > std::cos(l.outer_cone_angle);
        const float falloff = model == LightModel::Seed ? 1.0f / (1.0f + d) : 1.0f / (d * d);
        const float expected = inside ? 0.5f / kPi * l.intensity * cos_t * falloff : 0.0f;
        const float got = f.images.direct.at(x, y, 0);
        ASSERT_FALSE(std::isnan(got)) << x << "," << y;
        EXPECT_NEAR(got, expected, 1e-4f * expected + 1e-6f) << x << "," << y;
        (inside ? lit : dark) += 1;
      }
    EXPECT_GT(lit, 100);
    EXPECT_GT(dark, 100);
  }
}

// A Blender "Standard" lamp (1000 W = 54351 cd) 1 m above the floor, auto-exposed (scene/exposure.h):
// GL's image.direct is the closed form albedo / pi x N cos / d^2 x 2^stops, as the reference's is
// (tests/ref/exposure_test.cpp) and the path tracer's (tests/pt/light_kinds_plane_test.cpp).
TEST(GlLightKinds, PreExposedPhotometricLampIsTheClosedForm) {
  VCT_REQUIRE_GL();
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f, 1.0f, 0.0f);
  l.intensity = 54351.4f;
  Scene scene = plane_scene(l, 0.0f);
  pre_expose(scene, resolve_exposure(scene, ExposureMode::Auto, 0.0f));
  ASSERT_LT(scene.exposure.stops, -4);
  const FrameResult f = render_gl_frame(*ctx, scene, small_settings());
  int checked = 0;
  for (int y = 0; y < f.gbuffer.coverage.height; ++y)
    for (int x = 0; x < f.gbuffer.coverage.width; ++x) {
      if (f.gbuffer.coverage.at(x, y, 0) == 0.0f) continue;
      const vec3 p = f.gbuffer.position.rgb(x, y);
      if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;  // PCF taps stay on the -y face
      const float d = glm::length(l.position - p), cos_t = (l.position.y - p.y) / d;
      const float expected = 0.5f / kPi * l.intensity * cos_t / (d * d) * scene.exposure.scale;
      EXPECT_NEAR(f.images.direct.at(x, y, 0), expected, 1e-4f * expected) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace vct::gl::test
