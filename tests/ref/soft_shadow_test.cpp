// Cone-traced soft shadows: the light term equals the PCF path's where nothing occludes, and an
// occluder between the surface and the light takes the light away.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/shadow_map.h"
#include "stages/cone_sets.h"
#include "stages/soft_shadow.h"
#include "stages/voxelize.h"
#include "test_box_scene.h"

namespace vct {
namespace {

// A floor quad y=0 over [0,1]^2 seen from above, a spot light straight above it, and optionally a
// small horizontal occluder between them.
Scene floor_under_spot(bool occluder) {
  Scene s;
  s.source = "test:floor_under_spot";
  Material m;
  m.base_color_factor = vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallic_factor = 0.0f;
  m.roughness_factor = 0.7f;
  s.materials.push_back(m);
  test::add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, 0);
  if (occluder) test::add_quad(s, {0.4f, 0.5f, 0.4f}, {0.6f, 0.5f, 0.4f}, {0.6f, 0.5f, 0.6f}, {0.4f, 0.5f, 0.6f}, {0, -1, 0}, 0);
  s.bounds.add(vec3(0.5f, 1.0f, 0.5f));  // room for the light inside the volume
  Light l;
  l.position = vec3(0.5f, 0.95f, 0.5f);
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.intensity = 1.0f;
  l.outer_cone_angle = 1.2f;
  l.inner_cone_angle = 1.0f;
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  s.camera.position = vec3(0.5f, 2.5f, 0.5f);
  s.camera.forward = vec3(0.0f, -1.0f, 0.0f);
  s.camera.up = vec3(0.0f, 0.0f, -1.0f);
  s.camera.yfov = 0.5f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 5.0f;
  return s;
}

struct Frame {
  GBuffer g;
  Image pcf, soft, visibility;
  VoxelMips mips;
};

Frame render(const Scene& scene) {
  VctSettings s;
  s.width = s.height = 33;
  s.grid = 32;
  s.shadow_map_size = 256;
  Frame f;
  f.g = render_gbuffer(scene, s);
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, s);
  const VoxelGrid grid = inject_and_reduce(scene, voxelize_conservative(scene, s.grid), maps, s);
  f.mips = build_mips(grid.radiance, false);
  f.pcf = shade_direct(scene, f.g, maps, s);
  f.soft = shade_direct_soft(scene, f.g, f.mips, s, &f.visibility);
  return f;
}

TEST(SoftShadow, UnoccludedMatchesThePcfLightTerm) {
  const Frame f = render(floor_under_spot(false));
  ASSERT_GT(f.g.coverage.at(16, 16, 0), 0.0f);
  EXPECT_FLOAT_EQ(f.visibility.at(16, 16, 0), 1.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(f.pcf.at(16, 16, c), 0.0f);
    EXPECT_NEAR(f.soft.at(16, 16, c), f.pcf.at(16, 16, c), 1e-6f * f.pcf.at(16, 16, c));
  }
}

TEST(SoftShadow, OccluderDarkensTheConeVisibility) {
  const Frame f = render(floor_under_spot(true));
  // Floor pixels in the occluder's shadow ([0.29, 0.71] on the floor) but not hidden behind it
  // from the camera (|x - 0.5| > 0.125): dark in the shadow map and in the cone.
  int shadowed = 0;
  for (int y = 0; y < f.g.coverage.height; ++y) {
    for (int x = 0; x < f.g.coverage.width; ++x) {
      const vec3 p = f.g.position.rgb(x, y);
      const float dx = std::abs(p.x - 0.5f), dz = std::abs(p.z - 0.5f);
      if (f.g.coverage.at(x, y, 0) <= 0.0f || p.y > 1e-3f || std::max(dx, dz) < 0.14f || std::max(dx, dz) > 0.19f) continue;
      ++shadowed;
      EXPECT_LT(f.pcf.at(x, y, 0), 1e-6f) << x << "," << y;
      // Near the shadow's edge the 10-degree cone is partly past the occluder: a penumbra.
      EXPECT_LT(f.visibility.at(x, y, 0), 0.8f) << x << "," << y;
    }
  }
  EXPECT_GT(shadowed, 4);
  // A floor corner far outside the occluder's shadow stays lit.
  EXPECT_GT(f.visibility.at(2, 2, 0), 0.9f);
  // Straight under the occluder's centre (hidden from the camera) the cone is blocked most;
  // halfway to the shadow's edge, less; outside, hardly.
  const Scene scene = floor_under_spot(true);
  const VctSettings s;
  const Light& light = scene.lights[0];
  const float centre = trace_shadow_cone(f.mips, scene.volume, s, vec3(0.5f, 0.0f, 0.5f), light);
  const float half = trace_shadow_cone(f.mips, scene.volume, s, vec3(0.6f, 0.0f, 0.5f), light);
  const float outside = trace_shadow_cone(f.mips, scene.volume, s, vec3(0.9f, 0.0f, 0.5f), light);
  // The occluder is one voxel thick: at the lod the cone reaches there (about 1.2) its voxels are
  // about half opaque, so the cone lets about half the light through (VCT's light leaking, which
  // the seed reports too). Measured at 32^3: 0.52, then rising to 0.91 outside the shadow.
  EXPECT_LT(centre, 0.6f);
  EXPECT_LT(centre, half);
  EXPECT_LT(half, outside);
  EXPECT_GT(outside, 0.85f);
}

TEST(SoftShadow, SunConeRunsToTheVolumeExit) {
  // The same floor and occluder under a sun straight down instead of the spot: the cone has no
  // light position to stop at, it runs up through the occluder to where it leaves the volume, so
  // the occluder's shadow is the same while the light term is lux x cos everywhere.
  Scene scene = floor_under_spot(true);
  scene.lights[0].kind = LightKind::Directional;
  scene.lights[0].position = vec3(100.0f);  // meaningless for a sun: must not matter
  const Frame f = render(scene);
  const VctSettings s;
  const float centre = trace_shadow_cone(f.mips, scene.volume, s, vec3(0.5f, 0.0f, 0.5f), scene.lights[0]);
  const float outside = trace_shadow_cone(f.mips, scene.volume, s, vec3(0.9f, 0.0f, 0.5f), scene.lights[0]);
  EXPECT_LT(centre, 0.6f);
  EXPECT_GT(outside, 0.85f);
  // Unshadowed, the sun's radiance is lux x cos x BRDF whatever the light's "position".
  const vec3 p(0.9f, 0.0f, 0.1f), n(0, 1, 0), v = glm::normalize(scene.camera.position - p);
  SurfaceMaterial m;
  m.albedo = vec3(0.8f);
  m.metallic = 0.0f;
  m.roughness = 0.7f;
  const vec3 far = light_radiance(scene.lights[0], s, p, n, v, m);
  scene.lights[0].position = vec3(-3.0f);
  EXPECT_EQ(light_radiance(scene.lights[0], s, p, n, v, m), far);
  EXPECT_GT(far.r, 0.0f);
}

}  // namespace
}  // namespace vct
