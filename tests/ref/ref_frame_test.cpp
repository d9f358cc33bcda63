// The whole CPU frame: byte-identical for 1, 2 and 8 threads, and the composite adds up.
#include <gtest/gtest.h>

#include <cstring>

#include "core/parallel.h"
#include "shared/vct_shared.h"
#include "freedoms/reference_frame.h"
#include "test_box_scene.h"

namespace vct {
namespace {

Scene lit_box() {
  Scene s = test::closed_box(vec3(0.7f, 0.6f, 0.5f), vec3(0.0f));
  Light l;
  l.position = vec3(0.5f, 0.9f, 0.5f);
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.intensity = 2.0f;
  l.outer_cone_angle = 1.0f;
  s.lights.push_back(l);
  ParticleEmitter e;
  e.origin = vec3(0.5f, 0.2f, 0.5f);
  e.count = 16;
  s.emitters.push_back(e);
  return s;
}

Settings small_settings() {
  Settings s;
  s.vct.width = 48;
  s.vct.height = 40;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  s.vct.bounces = 2;
  s.vct.random_rotation = true;
  return s;
}

bool same_bytes(const Image& a, const Image& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

TEST(RefFrame, ByteIdenticalForOneTwoEightThreads) {
  const Scene scene = lit_box();
  for (bool soft : {false, true}) {
    Settings s = small_settings();
    s.vct.soft_shadows = soft;
    s.vct.anisotropic = soft;  // cover both sampler paths
    set_thread_count(1);
    const FrameResult one = render_ref_frame(scene, s);
    set_thread_count(2);
    const FrameResult two = render_ref_frame(scene, s);
    set_thread_count(8);
    const FrameResult eight = render_ref_frame(scene, s);
    set_thread_count(0);
    EXPECT_TRUE(same_bytes(one.images.final_image, two.images.final_image)) << "soft " << soft;
    EXPECT_TRUE(same_bytes(one.images.final_image, eight.images.final_image)) << "soft " << soft;
    EXPECT_TRUE(same_bytes(one.images.indirect_diffuse, eight.images.indirect_diffuse));
    EXPECT_EQ(one.multibounce_energy, eight.multibounce_energy);
  }
}

TEST(RefFrame, FinalIsTheSumOfItsComponents) {
  const Scene scene = lit_box();
  const FrameResult f = render_ref_frame(scene, small_settings());
  const FrameImages& im = f.images;
  double indirect = 0.0;
  for (int y = 0; y < im.final_image.height; ++y) {
    for (int x = 0; x < im.final_image.width; ++x) {
      const vec3 sum = im.direct.rgb(x, y) + im.diffuse_term.rgb(x, y) + im.specular_term.rgb(x, y) +
                       im.emission.rgb(x, y) + im.particles.rgb(x, y);
      const vec3 fin = im.final_image.rgb(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(fin[c], sum[c], 1e-5f * (1.0f + sum[c]));
      indirect += double(im.indirect_diffuse.rgb(x, y).x);
      // Dielectric seen head-on-ish: kd = (1 - F) with F from n.v; check the diffuse term.
      if (f.gbuffer.coverage.at(x, y, 0) > 0.0f) {
        const vec3 n = f.gbuffer.normal.rgb(x, y);
        const vec3 v = glm::normalize(scene.camera.position - f.gbuffer.position.rgb(x, y));
        const float fres = sh::fresnel_schlick(vec3(0.04f), 1.0f, std::max(glm::dot(n, v), 0.0f)).x;
        ASSERT_NEAR(im.diffuse_term.rgb(x, y).x, (1.0f - fres) * 0.7f * im.indirect_diffuse.rgb(x, y).x,
                    1e-5f * (1.0f + im.indirect_diffuse.rgb(x, y).x));
      }
    }
  }
  EXPECT_GT(indirect, 0.0);  // the lit floor lights the walls
  EXPECT_EQ(f.multibounce_energy.size(), 2u);
  EXPECT_GT(f.multibounce_energy[1], f.multibounce_energy[0]);
}

}  // namespace
}  // namespace vct
