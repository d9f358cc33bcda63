// The path tracer's primary-hit texture footprint (pt/ray_cone.h) against hand-computed lambdas,
// and against the G-buffer's exact GL 4.5 §8.14 lambda for the same pixel: on a plane facing the
// camera both measure one pixel's footprint in texels, so they agree to the spread angle's
// atan(x) ~ x approximation.
#include <gtest/gtest.h>

#include <cmath>

#include "pt/ray_cone.h"
#include "stages/uv_derivatives.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

// A 4 x 4 m plane at z = -d facing the camera at the origin, u = (x + 2) / 4, v = (y + 2) / 4,
// a 256 x 128 texture: 64 x 32 texels per metre, texel area / world area = 64 * 32.
Scene facing_plane(float d) {
  Scene s;
  const uint32_t m = test::add_material(s, test::lambertian(vec3(1.0f)));
  test::add_quad(s, {-2, -2, -d}, {4, 0, 0}, {0, 4, 0}, m);
  s.uv0.resize(s.positions.size());
  for (size_t i = 0; i < s.positions.size(); ++i)
    s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, (s.positions[i].y + 2.0f) / 4.0f);
  Texture t;
  t.width = 256;
  t.height = 128;
  s.textures.push_back(t);
  s.materials[m].base_color_texture.texture = 0;
  s.camera = test::look_at(vec3(0.0f), vec3(0, 0, -1), vec3(0, 1, 0), 1.0f);
  test::finish(s);
  return s;
}

TEST(RayCone, FacingPlaneLambdaIsTheConeWidthInTexels) {
  const Scene s = facing_plane(3.0f);
  const int height = 64;
  const float beta = pixel_spread_angle(s.camera, height);
  EXPECT_NEAR(beta, std::atan(2.0 * std::tan(0.5) / 64.0), 1e-7);
  // Straight ahead: t = 3, n . d = 1; W = 2 t tan(beta / 2); lambda = log2(W) + 0.5 log2(64 * 32).
  const double w = 2.0 * 3.0 * std::tan(double(beta) / 2.0);
  const SlotLods l = ray_cone_lods(s, 0, 3.0f, vec3(0, 0, -1), beta);
  EXPECT_NEAR(l.lambda[kSlotBaseColor], std::log2(w) + 0.5 * std::log2(64.0 * 32.0), 1e-5);
  EXPECT_EQ(l.lambda[kSlotNormal], 0.0);  // no normal map: level 0
  // Seen at 60 degrees from the normal the footprint stretches by 1 / cos = 2: one level more.
  const vec3 oblique(std::sin(1.0471976f), 0.0f, -std::cos(1.0471976f));
  EXPECT_NEAR(ray_cone_lods(s, 0, 3.0f, oblique, beta).lambda[kSlotBaseColor],
              l.lambda[kSlotBaseColor] + 1.0, 1e-5);
}

TEST(RayCone, AgreesWithTheGBufferLambdaOnAFacingPlane) {
  // A square texture (the cone is isotropic): 256 x 256 on the 4 m plane, 64 texels per metre.
  Scene s = facing_plane(3.0f);
  s.textures[0].height = 256;
  const int size = 64;
  const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  // The centre pixel (32, 32): the G-buffer's rho = 64 texels/m * 2 * 3 tan(0.5) / 64 per pixel.
  const SurfaceLods g = pixel_lods(s, 0, ScreenBarycentrics(s, 0, vp, size, size), 32, 32);
  const double gl_lambda = std::log2(64.0 * 2.0 * 3.0 * std::tan(0.5) / 64.0);
  ASSERT_NEAR(g.exact.lambda[kSlotBaseColor], gl_lambda, 1e-3);  // off-centre pixel: cos^-2 ~ 1e-4
  const float beta = pixel_spread_angle(s.camera, size);
  const SlotLods c = ray_cone_lods(s, 0, 3.0f, vec3(0, 0, -1), beta);
  EXPECT_NEAR(c.lambda[kSlotBaseColor], gl_lambda, 1e-3);
}

}  // namespace
}  // namespace vct::pt
