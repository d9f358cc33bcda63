// Shadow maps: depth of a plane against the analytic window depth, and PCF on a hand-made map.
#include <gtest/gtest.h>

#include "stage_test_scene.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

Scene plane_under_spot() {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f));
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  Light l;
  l.position = vec3(0.1f, 1.0f, -0.2f);
  l.direction = glm::normalize(vec3(0.2f, -1.0f, 0.1f));
  l.outer_cone_angle = 0.6f;
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  return s;
}

TEST(ShadowMap, PlaneDepthMatchesTheAnalyticWindowDepth) {
  const Scene s = plane_under_spot();
  VctSettings st;
  st.shadow_map_size = 64;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, st);
  ASSERT_EQ(maps.size(), 1u);
  const ShadowMap& m = maps[0];
  const mat4 inv = glm::inverse(m.view_proj);
  int checked = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x) {
      const float nx = (float(x) + 0.5f) / 32.0f - 1.0f, ny = (float(63 - row) + 0.5f) / 32.0f - 1.0f;
      vec4 a = inv * vec4(nx, ny, -1.0f, 1.0f), b = inv * vec4(nx, ny, 1.0f, 1.0f);
      const vec3 pa = vec3(a) / a.w, pb = vec3(b) / b.w;
      const vec3 hit = pa + (pb - pa) * (pa.y / (pa.y - pb.y));  // ray meets y = 0
      const vec4 c = m.view_proj * vec4(hit, 1.0f);
      ASSERT_LT(std::abs(hit.x), 2.0f);
      EXPECT_NEAR(m.depth.at(x, row, 0), c.z / c.w * 0.5f + 0.5f, 2e-5f) << x << "," << row;
      ++checked;
    }
  EXPECT_EQ(checked, 64 * 64);
}

TEST(ShadowMap, UpVectorIsRobustForAxisAlignedSpots) {
  Light l;
  l.position = vec3(0.0f, 0.0f, 2.0f);
  l.direction = vec3(0.0f, 0.0f, -1.0f);  // parallel to the default up (+z)
  Bounds3 b;
  b.add(vec3(-1.0f));
  b.add(vec3(1.0f));
  const mat4 vp = spot_light_view_proj(l, b);
  const vec4 c = vp * vec4(0.0f, 0.0f, 0.0f, 1.0f);  // a point on the axis maps to the centre
  EXPECT_NEAR(c.x / c.w, 0.0f, 1e-6f);
  EXPECT_NEAR(c.y / c.w, 0.0f, 1e-6f);
  for (int i = 0; i < 16; ++i) EXPECT_TRUE(std::isfinite(vp[i / 4][i % 4]));
}

TEST(ShadowMap, PcfCountsLitTapsOnAHandMadeMap) {
  ShadowMap m;  // orthographic identity: world = NDC
  m.depth = Image(8, 8, 1, 1.0f);
  for (int row = 0; row < 8; ++row)
    for (int x = 0; x < 4; ++x) m.depth.at(x, row, 0) = 0.3f;  // occluder over the left half
  VctSettings st;
  st.shadow_bias = 0.0005f;
  const float z = 0.2f;  // window depth 0.6: behind the occluder
  const auto at_col = [](float u) { return u / 8.0f * 2.0f - 1.0f; };
  st.pcf_kernel = 3;
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(3.5f), 0.1f, z), st), 3.0f / 9.0f);  // taps at cols 2,3,4
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(4.5f), 0.1f, z), st), 6.0f / 9.0f);  // cols 3,4,5
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(1.5f), 0.1f, z), st), 0.0f);
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(6.5f), 0.1f, z), st), 1.0f);
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(1.5f), 0.1f, -0.6f), st), 1.0f);  // in front: lit
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(0.5f), 0.1f, z), st), 0.0f);  // clamp to edge
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(1.5f, 0.1f, z), st), 1.0f);          // outside: lit
  st.pcf_kernel = 4;  // offsets -1.5 .. 1.5: cols 2,3,4,5
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(3.5f), 0.1f, z), st), 0.5f);
  st.pcf_kernel = 1;
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(3.5f), 0.1f, z), st), 0.0f);
  // Bias: a point just behind the stored depth (within the bias) is lit.
  EXPECT_FLOAT_EQ(shadow_visibility(m, vec3(at_col(1.5f), 0.1f, (0.3f + 0.0004f) * 2.0f - 1.0f), st), 1.0f);
}

}  // namespace
}  // namespace vct

namespace vct {
namespace {
// An engine's spot frustum (issue 21: fov 110 degrees, near 0.01, far 3) replaces the oracle's
// rule: a point on the axis at distance d maps to window depth of a GL perspective with those
// planes, z_w = (f (d - n)) / (d (f - n)), and a point 54 degrees off the axis (inside 55) lands
// inside the map although the oracle's own fov (twice a 30 degree cone) would put it outside.
TEST(ShadowConventions, EngineFrustumFromSettings) {
  Light l;
  l.position = vec3(0.0f);
  l.direction = vec3(0.0f, 0.0f, -1.0f);
  l.outer_cone_angle = glm::radians(30.0f);
  Bounds3 b;
  b.lo = vec3(-1.0f);
  b.hi = vec3(1.0f);
  VctSettings s;
  s.shadow_fov_deg = 110.0f;
  s.shadow_near = 0.01f;
  s.shadow_far = 3.0f;
  const mat4 vp = spot_light_view_proj(l, b, s);
  const float d = 1.5f, n = 0.01f, f = 3.0f;
  const vec4 c = vp * vec4(0.0f, 0.0f, -d, 1.0f);
  EXPECT_NEAR(c.z / c.w * 0.5f + 0.5f, f * (d - n) / (d * (f - n)), 1e-6f);
  const float off = std::tan(glm::radians(54.0f));
  const vec4 e = vp * vec4(off, 0.0f, -1.0f, 1.0f);
  EXPECT_LT(std::abs(e.x / e.w), 1.0f);
  const vec4 e0 = spot_light_view_proj(l, b) * vec4(off, 0.0f, -1.0f, 1.0f);
  EXPECT_GT(std::abs(e0.x / e0.w), 1.0f);
  // Zero keeps the oracle's rule: the default settings give the two-argument matrix.
  const mat4 a = spot_light_view_proj(l, b, VctSettings{}), a2 = spot_light_view_proj(l, b);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(a[i][j], a2[i][j]);
}
}  // namespace
}  // namespace vct
