// An engine's shadow projections (settings shadow_view_proj, shadow_ortho_box; issue 21): the
// text reads back to the same floats, a light named by a matrix gets exactly that matrix, and a
// directional light's box equal to the oracle's fitted one gives the oracle's matrix bit for bit.
#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/light_matrices.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

Scene sun_scene() {
  Scene s;
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(vec3(0.3f, -1.0f, 0.2f));
  s.lights.push_back(sun);
  s.volume.origin = vec3(-1.0f);
  s.volume.size = 2.0f;
  return s;
}

TEST(LightMatrices, TextReadsBackToTheSameFloats) {
  mat4 m(0.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = 1.0f / float(3 + c * 4 + r) - 0.1f * float(r);
  const std::map<int, mat4> back = parse_light_matrices(light_matrix_text(2, m) + "; " + light_matrix_text(0, mat4(1.0f)));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back.at(2), m);
  EXPECT_EQ(back.at(0), mat4(1.0f));
  // Column-major: the 13th number is column 3, row 0 (a translation in x).
  EXPECT_EQ(parse_light_matrices("0:1,0,0,0, 0,1,0,0, 0,0,1,0, 5,0,0,1").at(0)[3][0], 5.0f);
}

TEST(LightMatrices, MalformedTextIsBadInput) {
  for (const char* bad : {"0:1,2", "x:1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1", "-1:1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1",
                          "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1", "0:1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,inf"})
    EXPECT_THROW(parse_light_matrices(bad), InputError) << bad;
  const std::string twice = light_matrix_text(0, mat4(1.0f)) + ";" + light_matrix_text(0, mat4(1.0f));
  EXPECT_THROW(parse_light_matrices(twice), InputError);
  EXPECT_THROW(parse_ortho_boxes("0:-1,1,-1,1,2,1"), InputError);  // near > far
  EXPECT_EQ(parse_ortho_boxes("0:-1,1,-2,2,0.5,4").at(0)[3], 2.0f);
}

TEST(LightMatrices, DeclaredMatrixReplacesTheLightsOwn) {
  const Scene scene = sun_scene();
  VctSettings s;
  const mat4 m = glm::ortho(-3.0f, 3.0f, -3.0f, 3.0f, 0.0f, 6.0f) * directional_light_view(scene.lights[0], scene.volume);
  s.shadow_view_proj = light_matrix_text(0, m);
  EXPECT_EQ(light_view_proj(scene, 0, s), parse_light_matrices(s.shadow_view_proj).at(0));
  EXPECT_NE(light_view_proj(scene, 0, s), directional_light_view_proj(scene.lights[0], scene.volume));
}

TEST(LightMatrices, OrthoBoxEqualToTheFittedOneGivesTheOraclesMatrix) {
  // The oracle fits the volume's 8 corners in the light view (x, y, and near/far = -z range); the
  // same box declared as text gives the same matrix, bit for bit.
  const Scene scene = sun_scene();
  const mat4 view = directional_light_view(scene.lights[0], scene.volume);
  vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int c = 0; c < 8; ++c) {
    const vec3 corner = scene.volume.origin + scene.volume.size * vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    const vec3 v = vec3(view * vec4(corner, 1.0f));
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  std::ostringstream box;
  box.precision(9);
  box << "0:" << lo.x << "," << hi.x << "," << lo.y << "," << hi.y << "," << -hi.z << "," << -lo.z;
  VctSettings s;
  s.shadow_ortho_box = box.str();
  EXPECT_EQ(light_view_proj(scene, 0, s), directional_light_view_proj(scene.lights[0], scene.volume));
  // A box twice as wide is another matrix.
  s.shadow_ortho_box = "0:" + std::to_string(2 * lo.x) + "," + std::to_string(2 * hi.x) + "," + std::to_string(lo.y) +
                       "," + std::to_string(hi.y) + "," + std::to_string(-hi.z) + "," + std::to_string(-lo.z);
  EXPECT_NE(light_view_proj(scene, 0, s)[0][0], directional_light_view_proj(scene.lights[0], scene.volume)[0][0]);
}

TEST(LightMatrices, BoxOnASpotOrBothOnOneLightIsBadInput) {
  Scene scene = sun_scene();
  VctSettings s;
  s.shadow_ortho_box = "0:-1,1,-1,1,0.1,5";
  s.shadow_view_proj = light_matrix_text(0, mat4(1.0f));
  EXPECT_THROW(light_view_proj(scene, 0, s), InputError);
  s.shadow_view_proj.clear();
  scene.lights[0].kind = LightKind::Spot;
  EXPECT_THROW(light_view_proj(scene, 0, s), InputError);
}

}  // namespace
}  // namespace vct
