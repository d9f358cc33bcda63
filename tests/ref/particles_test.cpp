// The stateless particle function (shared with GLSL) and the particle layers.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/vct_shared.h"
#include "stages/particles.h"

namespace vct {
namespace {

ParticleEmitter still_emitter() {
  ParticleEmitter e;
  e.origin = vec3(0.5f, 0.25f, 0.5f);
  e.count = 4;
  e.lifetime = 2.0f;
  e.spawn_extent = vec3(0.0f);
  e.velocity_min = e.velocity_max = vec3(0.0f, 1.0f, 0.0f);
  e.acceleration = vec3(0.0f, 0.5f, 0.0f);
  e.color_start = vec3(4.0f, 2.0f, 1.0f);
  e.color_end = vec3(0.0f);
  e.size_start = 0.1f;
  e.size_end = 0.02f;
  return e;
}

TEST(Particles, UniformlyAcceleratedMotionAndLinearAttributes) {
  const sh::ParticleEmitterBlock b = emitter_block(still_emitter());
  // Particle 1 of 4 is born at 1/4 * 2 s = 0.5 s; at t = 1.0 s its age is 0.5 s (u = 0.25).
  const sh::ParticleState p = sh::particle_state(b, 0u, 1u, 1.0f);
  EXPECT_NEAR(p.position_radius.y, 0.25f + 1.0f * 0.5f + 0.5f * 0.5f * 0.25f, 1e-6f);
  EXPECT_NEAR(p.position_radius.x, 0.5f, 1e-7f);
  EXPECT_NEAR(p.position_radius.w, 0.1f + (0.02f - 0.1f) * 0.25f, 1e-7f);
  EXPECT_NEAR(p.color_age.x, 3.0f, 1e-6f);
  EXPECT_NEAR(p.color_age.w, 0.25f, 1e-7f);
  // One lifetime later it has respawned at the same age.
  EXPECT_NEAR(sh::particle_state(b, 0u, 1u, 3.0f).color_age.w, 0.25f, 1e-6f);
}

TEST(Particles, DeterministicAndDifferentPerIdAndLife) {
  ParticleEmitter e = still_emitter();
  e.spawn_extent = vec3(0.1f);
  e.velocity_min = vec3(-0.2f, 0.5f, -0.2f);
  const sh::ParticleEmitterBlock b = emitter_block(e);
  const sh::ParticleState a1 = sh::particle_state(b, 0u, 2u, 1.7f);
  const sh::ParticleState a2 = sh::particle_state(b, 0u, 2u, 1.7f);
  EXPECT_EQ(a1.position_radius, a2.position_radius);
  EXPECT_EQ(a1.color_age, a2.color_age);
  EXPECT_NE(sh::particle_state(b, 0u, 3u, 1.7f).position_radius.x, a1.position_radius.x);
  EXPECT_NE(sh::particle_state(b, 1u, 2u, 1.7f).position_radius.x, a1.position_radius.x);
  // Same age in the next life: new randoms, so a different spawn point.
  EXPECT_NE(sh::particle_state(b, 0u, 2u, 3.7f).position_radius.x, a1.position_radius.x);
  // Spawn box respected: |x - origin.x| <= extent + |v| * age.
  for (uint32_t id = 0; id < 4; ++id) {
    const sh::ParticleState p = sh::particle_state(b, 0u, id, 0.9f);
    const float age = p.color_age.w * e.lifetime;
    EXPECT_LE(std::abs(p.position_radius.x - e.origin.x), 0.1f + 0.2f * age + 1e-6f);
  }
}

TEST(Particles, VoxelInjectionAddsDiscPowerOverVoxelFace) {
  Scene scene;
  scene.emitters.push_back(still_emitter());
  scene.emitters[0].count = 1;
  scene.volume.origin = vec3(0.0f);
  scene.volume.size = 2.0f;
  VctSettings s;
  s.time = 0.0f;  // age 0: at the origin (0.5, 0.25, 0.5), radius 0.1, colour start
  Volume radiance(8, 8, 8, 4);
  radiance.set_rgba(2, 1, 2, vec4(1.0f, 1.0f, 1.0f, 1.0f));
  add_particles_to_voxels(scene, s, radiance);
  const float voxel = 2.0f / 8.0f;
  const float gain = 0.5f * kPi * 0.01f / (voxel * voxel);
  EXPECT_NEAR(radiance.rgba(2, 1, 2).x, 1.0f + 4.0f * gain, 1e-5f);
  EXPECT_NEAR(radiance.rgba(2, 1, 2).z, 1.0f + 1.0f * gain, 1e-5f);
  EXPECT_EQ(radiance.rgba(2, 1, 2).w, 1.0f);  // opacity untouched
}

TEST(Particles, SplatIsDepthTestedAgainstTheGBuffer) {
  Scene scene;
  scene.emitters.push_back(still_emitter());
  scene.emitters[0].count = 1;
  scene.camera.position = vec3(0.5f, 0.25f, 3.0f);
  scene.camera.forward = vec3(0.0f, 0.0f, -1.0f);
  VctSettings s;
  s.time = 0.0f;
  GBuffer g;
  g.coverage = Image(33, 33, 1, 0.0f);
  g.depth = Image(33, 33, 1, 0.0f);
  const Image open = render_particles(scene, g, s);
  // The centre pixel looks straight at the particle centre: full profile, colour start.
  EXPECT_NEAR(open.rgb(16, 16).x, 4.0f, 1e-3f);
  EXPECT_EQ(open.rgb(0, 0), vec3(0.0f));
  // An opaque surface in front (depth 0) hides it.
  g.coverage = Image(33, 33, 1, 1.0f);
  const Image hidden = render_particles(scene, g, s);
  EXPECT_EQ(hidden.rgb(16, 16), vec3(0.0f));
}

}  // namespace
}  // namespace vct
