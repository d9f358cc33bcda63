// Fire particles in the path tracer: one motionless particle above a Lambertian plane. It lights
// the plane as an isotropic point light of intensity colour * pi r^2 / 2 (noise-free: one
// particle is picked with probability 1), which lands in the one-bounce indirect AOVs as the
// voxel injection does in VCT, and the camera sees its disc additively in pt_particles.
#include <gtest/gtest.h>

#include <cmath>

#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "shared/vct_shared.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

TEST(Particles, PointLightOnPlaneAndCameraDisc) {
  Scene s;
  const vec3 albedo(0.6f, 0.5f, 0.4f);
  const uint32_t m = test::add_material(s, test::lambertian(albedo));
  test::add_quad(s, vec3(-10, 0, -10), vec3(0, 0, 20), vec3(20, 0, 0), m);
  ParticleEmitter e;
  e.origin = vec3(0.0f, 0.5f, 0.0f);
  e.count = 1;
  e.lifetime = 1.0f;
  e.spawn_extent = vec3(0.0f);
  e.velocity_min = e.velocity_max = e.acceleration = vec3(0.0f);
  e.color_start = vec3(4.0f, 2.0f, 1.0f);
  e.color_end = vec3(2.0f, 1.0f, 0.0f);
  e.size_start = 0.2f;
  e.size_end = 0.1f;
  s.emitters.push_back(e);
  s.camera = test::look_at(vec3(0.0f, 3.0f, 0.0f), vec3(0.0f), vec3(0, 0, -1), 0.8f);
  test::finish(s);

  PtSettings ps;
  ps.width = ps.height = 33;  // odd: the centre pixel looks straight down through the particle
  ps.max_depth = 1;
  const ParticleOptions opt{true, 0.5f};  // age 0.5: colour and radius halfway
  const PathTracer pt(s, ps, opt);
  ASSERT_EQ(pt.particles().size(), 1u);
  Accumulator acc(ps.width, ps.height);
  pt.render(acc, 2);

  const vec3 colour(3.0f, 1.5f, 0.5f);
  const float r = 0.15f;
  const vec3 intensity = colour * (0.5f * kPi * r * r);
  const Image diffuse = acc.mean(kIndirectDiffuse), layer = acc.mean(kParticles), full = acc.mean(kFull);
  // Camera straight above: the centre pixel's floor point is (0,0,0), under the particle.
  const vec3 e_centre = intensity / (0.5f * 0.5f);
  const vec3 expected_centre = albedo * kInvPi * e_centre;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(diffuse.at(16, 16, c), expected_centre[c], 1e-3f * expected_centre[c]);
  // The disc covers the centre pixel with (nearly) the full profile, and not the corners.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(layer.at(16, 16, c), colour[c], 1e-3f * colour[c]);
  EXPECT_EQ(layer.rgb(0, 0), vec3(0.0f));
  // full = particles + the light they put on the floor (max_depth 1: nothing else).
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(full.at(16, 16, c), colour[c] + expected_centre[c], 1e-3f * (colour[c] + expected_centre[c]));
  // Off-centre floor point: inverse square and cosine.
  const Image direct = acc.mean(kDirect);
  EXPECT_EQ(direct.rgb(5, 9), vec3(0.0f));

  // Particles disabled: no layer, no light.
  const PathTracer off(s, ps, ParticleOptions{false, 0.5f});
  Accumulator acc_off(ps.width, ps.height);
  off.render(acc_off, 1);
  for (float v : acc_off.mean(kFull).data) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace vct::pt
