// No light leaks through bent shading normals: a spot light below a plane whose interpolated
// normals lean toward it must not light the plane's top, and the camera-side result must equal the
// flat-normal result wherever the light is above the plane (the shading normal only changes the
// BRDF, never which side of the surface is lit). Two mechanisms guard this: eval_bsdf rejects
// directions below the geometric plane, and the shadow ray from the lifted point crosses the
// surface itself; this test checks the outcome (either alone keeps it passing).
#include <gtest/gtest.h>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

Scene bent_plane(const vec3& light_pos, const vec3& light_dir, const vec3& normal) {
  Scene s;
  const uint32_t m = test::add_material(s, test::lambertian(vec3(0.8f)));
  test::add_quad(s, vec3(-1, 0, -1), vec3(0, 0, 2), vec3(2, 0, 0), m);  // y = 0, winding +y
  for (vec3& n : s.normals) n = glm::normalize(normal);
  Light l;
  l.position = light_pos;
  l.direction = glm::normalize(light_dir);
  l.intensity = 10.0f;
  l.outer_cone_angle = 1.5f;
  l.inner_cone_angle = 1.4f;
  s.lights.push_back(l);
  s.camera = test::look_at(vec3(0.0f, 2.0f, 0.5f), vec3(0.0f), vec3(0, 0, -1), 1.0f);
  test::finish(s);
  return s;
}

Image direct_of(const Scene& s) {
  PtSettings ps;
  ps.width = ps.height = 16;
  const PathTracer pt(s, ps);
  Accumulator acc(16, 16);
  pt.render(acc, 1);
  return acc.mean(kDirect);
}

TEST(LightLeak, LightBelowBentPlaneDoesNotLightIt) {
  // Shading normals lean 73 degrees toward +x; the light sits below the plane at +x, grazing,
  // so n_shading . l > 0 while the geometric normal says the light is behind the surface.
  const Scene s = bent_plane(vec3(3.0f, -0.2f, 0.0f), vec3(-1.0f, 0.05f, 0.0f), vec3(1.0f, 0.3f, 0.0f));
  for (float v : direct_of(s).data) EXPECT_EQ(v, 0.0f);
}

TEST(LightLeak, LightAboveIsSeenThroughTheShadingNormal) {
  // Same bent normals, light above: lit, and differently from flat normals (the BRDF uses the
  // shading normal), so the previous test's zeros are not an artefact of a dark setup.
  const vec3 pos(3.0f, 0.2f, 0.0f), dir(-1.0f, -0.05f, 0.0f);
  const Image bent = direct_of(bent_plane(pos, dir, vec3(1.0f, 0.3f, 0.0f)));
  const Image flat = direct_of(bent_plane(pos, dir, vec3(0.0f, 1.0f, 0.0f)));
  float bent_sum = 0.0f, flat_sum = 0.0f;
  for (float v : bent.data) bent_sum += v;
  for (float v : flat.data) flat_sum += v;
  EXPECT_GT(flat_sum, 0.0f);
  EXPECT_GT(bent_sum, 2.0f * flat_sum);  // leaning toward a grazing light raises n.l
}

}  // namespace
}  // namespace vct::pt
