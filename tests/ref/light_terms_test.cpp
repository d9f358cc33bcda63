// A fragment's light split per light (freedoms/light_terms.h): the change bound keeps each light
// behind the surface on its own, so one light's signed change cannot cancel another's.
#include <gtest/gtest.h>

#include "freedoms/light_terms.h"

namespace vct {
namespace {

LightTerms terms(vec3 rest, std::vector<vec3> per_light, std::vector<float> n_dot_l) {
  LightTerms t;
  t.rest = rest;
  t.per_light = std::move(per_light);
  t.n_dot_l = std::move(n_dot_l);
  return t;
}

// Both lights in front: the change is that of the sum (one raises, the other lowers: 0.1 - 0.1).
TEST(LightTerms, LightsInFrontChangeTogether) {
  const LightTerms a = terms(vec3(0.0f), {vec3(0.5f), vec3(0.3f)}, {0.5f, 0.3f});
  const LightTerms b = terms(vec3(0.0f), {vec3(0.4f), vec3(0.4f)}, {0.4f, 0.4f});
  EXPECT_NEAR(light_change(a, b), 0.0f, 1e-7f);
}

// Light 2 behind the surface in b (signed -0.1) and in front in a (+0.05, a horizon crossing):
// GL's clamped change is 0.05, the signed one 0.15; light 1 falls by 0.15 (in front of both). Summed
// first, the signed changes would cancel to 0; kept apart the bound is 0.15 + 0.15.
TEST(LightTerms, ALightBehindTheSurfaceCountsOnItsOwn) {
  const LightTerms a = terms(vec3(0.0f), {vec3(0.35f), vec3(0.05f)}, {0.35f, 0.05f});
  const LightTerms b = terms(vec3(0.0f), {vec3(0.5f), vec3(-0.1f)}, {0.5f, -0.1f});
  EXPECT_NEAR(light_change(a, b), 0.3f, 1e-6f);
}

// Emission and bounce change with the lights in front.
TEST(LightTerms, EmissionChangesWithTheFront) {
  const LightTerms a = terms(vec3(0.2f, 0.0f, 0.0f), {vec3(0.1f)}, {0.5f});
  const LightTerms b = terms(vec3(0.0f), {vec3(0.3f)}, {0.5f});
  EXPECT_NEAR(light_change(a, b), 0.2f, 1e-6f);  // R: 0.2 - 0.2 = 0; G and B: 0.2
}

}  // namespace
}  // namespace vct
