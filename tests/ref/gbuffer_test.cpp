// The G-buffer of one quad against the analytic view.
#include <gtest/gtest.h>

#include <cmath>

#include "stage_test_scene.h"
#include "stages/gbuffer.h"

namespace vct {
namespace {

Scene quad_scene(bool facing_camera) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.2f, 0.4f, 0.6f), vec3(0.0f), 0.25f, 0.75f);
  const vec3 n = facing_camera ? vec3(0, 0, 1) : vec3(0, 0, -1);
  test::add_quad(s, {-0.7f, -0.45f, -2}, {0.6f, -0.45f, -2}, {0.6f, 0.55f, -2}, {-0.7f, 0.55f, -2}, n, m);
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
  s.volume = fit_volume(s.bounds);
  return s;
}

void check_quad(bool facing) {
  const Scene s = quad_scene(facing);
  VctSettings st;
  st.width = 16;
  st.height = 12;
  const GBuffer g = render_gbuffer(s, st);
  const float ty = std::tan(0.5f), tx = ty * 16.0f / 12.0f;
  const mat4 proj = s.camera.projection(16.0f / 12.0f);
  int covered = 0;
  for (int row = 0; row < 12; ++row)
    for (int x = 0; x < 16; ++x) {
      const float nx = (float(x) + 0.5f) / 8.0f - 1.0f, ny = (float(11 - row) + 0.5f) / 6.0f - 1.0f;
      const vec3 p(nx * tx * 2.0f, ny * ty * 2.0f, -2.0f);  // where the centre's ray meets z = -2
      const bool inside = p.x > -0.7f && p.x < 0.6f && p.y > -0.45f && p.y < 0.55f;
      ASSERT_EQ(g.coverage.at(x, row, 0), inside ? 1.0f : 0.0f) << x << "," << row;
      if (!inside) {
        EXPECT_EQ(g.depth.at(x, row, 0), 1.0f);
        continue;
      }
      ++covered;
      // Vertices snap to 1/256 pixel (0.18 world units per pixel here): up to ~7e-4 of shift.
      EXPECT_NEAR(glm::distance(g.position.rgb(x, row), p), 0.0f, 8e-4f);
      EXPECT_EQ(g.normal.rgb(x, row), vec3(0, 0, 1));  // faces the camera either way
      EXPECT_EQ(g.albedo.rgb(x, row), vec3(0.2f, 0.4f, 0.6f));
      EXPECT_EQ(g.material.at(x, row, 0), 0.25f);
      EXPECT_EQ(g.material.at(x, row, 1), 0.75f);
      const vec4 c = proj * vec4(p, 1.0f);
      EXPECT_NEAR(g.depth.at(x, row, 0), c.z / c.w * 0.5f + 0.5f, 1e-5f);  // a plane at constant z: depth unaffected by snapping
    }
  // Hand count: x centres with |X| in range: 9 columns; rows: 6 (checked above pixel by pixel).
  EXPECT_GT(covered, 30);
}

TEST(GBuffer, OneQuadMatchesTheAnalyticView) { check_quad(true); }
TEST(GBuffer, BackFacingQuadNormalIsFlippedTowardTheCamera) { check_quad(false); }

// Tangent-space normal maps in both encodings: a 1x1 texel (192, 128, 255) tilts the normal toward
// the tangent. Three-channel: tn = (2*192/255-1, 2*128/255-1, 1); two-channel: z reconstructed.
void check_normal_map(bool two_channel) {
  Scene s = quad_scene(true);
  Texture t;
  t.width = t.height = 1;
  t.rgba8 = {192, 128, 255, 255};
  s.textures.push_back(t);
  s.materials[0].normal_texture.texture = 0;
  s.materials[0].normal_two_channel = two_channel;
  s.tangents.assign(s.positions.size(), vec4(1.0f, 0.0f, 0.0f, 1.0f));
  VctSettings st;
  st.width = 16;
  st.height = 12;
  const GBuffer g = render_gbuffer(s, st);
  const float x = 192.0f / 255.0f * 2.0f - 1.0f, y = 128.0f / 255.0f * 2.0f - 1.0f;
  const float z = two_channel ? std::sqrt(1.0f - x * x - y * y) : 1.0f;
  const vec3 expected = glm::normalize(vec3(x, y, z));  // tangent = +x, bitangent = +y, normal = +z
  int n = 0;
  for (int row = 0; row < 12; ++row)
    for (int px = 0; px < 16; ++px)
      if (g.coverage.at(px, row, 0) > 0.0f) {
        EXPECT_NEAR(glm::distance(g.normal.rgb(px, row), expected), 0.0f, 1e-5f);
        ++n;
      }
  EXPECT_GT(n, 30);
}

TEST(GBuffer, NormalMapThreeChannel) { check_normal_map(false); }
TEST(GBuffer, NormalMapTwoChannelReconstructsZ) { check_normal_map(true); }

}  // namespace
}  // namespace vct
