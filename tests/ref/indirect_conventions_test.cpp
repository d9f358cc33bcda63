// An engine's conventions for the frame's indirect terms (issue 21): a gain on the indirect diffuse
// (setting indirect_diffuse_gain, the source design's u_restitution) and the composite's Fresnel
// for the indirect terms (indirect_fresnel = schlick_roughness, its FresnelSchlickRoughness).
// Hand values, and a small frame whose composite is checked term by term.
#include <gtest/gtest.h>

#include "stages/composite.h"
#include "freedoms/reference_frame.h"
#include "test_box_scene.h"

namespace vct {
namespace {

TEST(IndirectFresnel, SchlickRoughnessCapsTheGrazingReflectanceByRoughness) {
  const vec3 f0(0.04f);
  // Roughness 1: f90 = max(1 - 1, 0.04) = f0, so F = f0 at every angle (Schlick: 0.04 + 0.96 m^5).
  EXPECT_FLOAT_EQ(indirect_fresnel(IndirectFresnel::SchlickRoughness, f0, 1.0f, 1.0f, 0.3f).x, 0.04f);
  EXPECT_FLOAT_EQ(indirect_fresnel(IndirectFresnel::Schlick, f0, 1.0f, 1.0f, 0.3f).x,
                  0.04f + 0.96f * 0.7f * 0.7f * 0.7f * 0.7f * 0.7f);  // 0.2013472
  // Roughness 0.5: f90 = 0.75. Grazing (cos 0): F = 0.75; cos 0.5: 0.04 + 0.71 / 32 = 0.0621875.
  EXPECT_FLOAT_EQ(indirect_fresnel(IndirectFresnel::SchlickRoughness, f0, 1.0f, 0.5f, 0.0f).x, 0.75f);
  EXPECT_FLOAT_EQ(indirect_fresnel(IndirectFresnel::SchlickRoughness, f0, 1.0f, 0.5f, 0.5f).x, 0.0621875f);
  // Per channel: a metal's f0 above 1 - r^2 is its own grazing value (F = f0 throughout).
  const vec3 metal(0.9f, 0.2f, 0.04f);
  const vec3 f = indirect_fresnel(IndirectFresnel::SchlickRoughness, metal, 1.0f, 0.5f, 0.0f);
  EXPECT_FLOAT_EQ(f.x, 0.9f);
  EXPECT_FLOAT_EQ(f.y, 0.75f);
  EXPECT_FLOAT_EQ(f.z, 0.75f);
}

// The closed unit box, every wall emissive (so the cones see light), albedo 0.5, roughness 1;
// 16^3 voxels, 16x16 pixels, no lights.
FrameResult box_frame(float gain, IndirectFresnel fresnel) {
  const Scene scene = test::closed_box(vec3(0.5f), vec3(1.0f));
  Settings s;
  s.vct.grid = 16;
  s.vct.width = s.vct.height = 16;
  s.vct.particles = false;
  s.vct.indirect_diffuse_gain = gain;
  s.vct.indirect_fresnel = fresnel;
  return render_ref_frame(scene, s);
}

TEST(IndirectDiffuseGain, ScalesTheStageAndItsCompositeTerm) {
  const FrameResult one = box_frame(1.0f, IndirectFresnel::SchlickRoughness);
  const FrameResult gained = box_frame(0.15f, IndirectFresnel::SchlickRoughness);
  const Image& ind1 = one.images.indirect_diffuse;
  const Image& ind = gained.images.indirect_diffuse;
  int covered = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      if (gained.gbuffer.coverage.at(x, y, 0) <= 0.0f) continue;
      ++covered;
      for (int c = 0; c < 3; ++c) {
        ASSERT_GT(ind1.at(x, y, c), 0.1f);  // the walls' light reaches every pixel
        // The same cones, one float product more: exactly 0.15f x the ungained value.
        EXPECT_EQ(ind.at(x, y, c), 0.15f * ind1.at(x, y, c));
        // Roughness 1 under schlick_roughness: F = 0.04, kd = 0.96, so the composite's terms are
        // 0.96 x 0.5 x the gained diffuse and 0.04 x the specular cone.
        EXPECT_NEAR(gained.images.diffuse_term.at(x, y, c), 0.96f * 0.5f * ind.at(x, y, c), 1e-6f);
        EXPECT_NEAR(gained.images.specular_term.at(x, y, c), 0.04f * gained.images.indirect_specular.at(x, y, c),
                    1e-6f);
        EXPECT_NEAR(gained.images.final_image.at(x, y, c),
                    gained.images.direct.at(x, y, c) + gained.images.diffuse_term.at(x, y, c) +
                        gained.images.specular_term.at(x, y, c) + 1.0f /* emission */,
                    1e-5f);
      }
    }
  EXPECT_EQ(covered, 256);
}

TEST(IndirectFresnel, TheTwoFresnelsDifferByTheSchlickTermPerPixel) {
  // The same cones under both: per pixel, ours (f90 = 1) / schlick_roughness (roughness 1, F = f0)
  // is (0.04 + 0.96 (1 - n.v)^5) / 0.04, n.v from the G-buffer and the camera.
  const Scene scene = test::closed_box(vec3(0.5f), vec3(1.0f));
  const FrameResult ours = box_frame(1.0f, IndirectFresnel::Schlick);
  const FrameResult theirs = box_frame(1.0f, IndirectFresnel::SchlickRoughness);
  int grazing = 0, checked = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const vec3 p = ours.gbuffer.position.rgb(x, y), n = ours.gbuffer.normal.rgb(x, y);
      const float m = 1.0f - std::max(glm::dot(n, scene.camera.to_eye(p)), 0.0f);
      const float ratio = (0.04f + 0.96f * m * m * m * m * m) / 0.04f;
      if (theirs.images.specular_term.at(x, y, 0) < 1e-4f) continue;  // a cone that saw nothing
      ++checked;
      EXPECT_NEAR(ours.images.specular_term.at(x, y, 0) / theirs.images.specular_term.at(x, y, 0), ratio,
                  1e-4f * ratio);
      grazing += ratio > 1.5f;
    }
  EXPECT_GT(checked, 200);
  EXPECT_GT(grazing, 10);  // the corners of the view: F at least 0.06 where schlick_roughness keeps 0.04
}

}  // namespace
}  // namespace vct
