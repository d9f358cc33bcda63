// Shadow maps: depth of a plane against the analytic window depth, and PCF on a hand-made map.
#include <gtest/gtest.h>

#include "stage_test_scene.h"
#include "core/error.h"
#include "core/pcf_taps.h"
#include "core/settings_table.h"
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

namespace vct {
namespace {
// An engine's PCF (issue 21): the hand-made map of PcfCountsLitTapsOnAHandMadeMap (columns 0..3
// occluded at depth 0.3, the point at window depth 0.6 behind it), looked up with a tap list and
// with GL LINEAR's bilinear compare (GL 4.5 section 8.23.1: texels i0 = floor(u - 0.5) and i0 + 1,
// weights 1 - alpha and alpha, alpha = frac(u - 0.5)); every expected value is worked by hand.
ShadowMap left_half_occluded() {
  ShadowMap m;  // orthographic identity: world = NDC
  m.depth = Image(8, 8, 1, 1.0f);
  for (int row = 0; row < 8; ++row)
    for (int x = 0; x < 4; ++x) m.depth.at(x, row, 0) = 0.3f;
  return m;
}
vec3 behind_at_column(float u) { return vec3(u / 8.0f * 2.0f - 1.0f, 0.1f, 0.2f); }

TEST(ShadowConventions, LinearCompareWeightsTheFourTexelsBilinearly) {
  const ShadowMap m = left_half_occluded();
  VctSettings st;
  st.pcf_taps = "0,0";
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.25f), st), 1.0f);  // nearest: column 4
  st.shadow_compare = ShadowCompare::Linear;
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.0f), st), 0.5f);    // columns 3, 4 at 1/2
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.25f), st), 0.75f);  // alpha = 0.75
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(3.5f), st), 0.0f);    // column 3's centre
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.5f), st), 1.0f);
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(0.2f), st), 0.0f);    // clamp to edge
}

TEST(ShadowConventions, TapListWithFractionalOffsets) {
  const ShadowMap m = left_half_occluded();
  VctSettings st;
  st.pcf_taps = "-1,0 -0.3333333,0 0.3333333,0 1,0";  // gidemo's +-1/3, +-1 along x
  // u = 4.5: taps at 3.5, 4.17, 4.83, 5.5 -> columns 3, 4, 4, 5.
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.5f), st), 0.75f);
  // u = 4.2: 3.2, 3.87, 4.53, 5.2 -> columns 3, 3, 4, 5.
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.2f), st), 0.5f);
  // Linear: 3.5 -> column 3 alone (0); 4.17 -> alpha 2/3 on column 4; 4.83, 5.5 -> lit.
  st.shadow_compare = ShadowCompare::Linear;
  EXPECT_NEAR(shadow_visibility(m, behind_at_column(4.5f), st), (0.0f + 2.0f / 3.0f + 1.0f + 1.0f) / 4.0f, 1e-6f);
}

TEST(ShadowConventions, DefaultTapsAreThePcfKernelSquare) {
  VctSettings st;
  st.pcf_kernel = 2;
  const std::vector<vec2> t = pcf_tap_offsets(st);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0], vec2(-0.5f, -0.5f));
  EXPECT_EQ(t[3], vec2(0.5f, 0.5f));
  st.pcf_taps = "0.25,-1 2,3";
  EXPECT_EQ(pcf_tap_offsets(st), (std::vector<vec2>{{0.25f, -1.0f}, {2.0f, 3.0f}}));
}

TEST(ShadowConventions, MalformedTapListIsBadInput) {
  for (const char* bad : {"1", "1,x", "1,2,3", ",1", "17,0", "nan,0", "1,2 3"})
    EXPECT_THROW(parse_pcf_taps(bad), InputError) << bad;
  EXPECT_TRUE(parse_pcf_taps("  ").empty());
  Settings s;
  s.vct.pcf_taps = "1;2";
  EXPECT_THROW(validate_settings(s), InputError);
  const Settings t = with_setting(Settings{}, "shadow_compare", "linear", "--set");
  EXPECT_EQ(t.vct.shadow_compare, ShadowCompare::Linear);
  EXPECT_EQ(with_setting(Settings{}, "pcf_taps", "1,0 -1,0", "--set").vct.pcf_taps, "1,0 -1,0");
}
}  // namespace
}  // namespace vct

namespace vct {
namespace {
// An engine's depth format (issue 21): UNORM depth is the float window depth rounded to the
// nearest multiple of 1 / (2^b - 1); values worked by hand, then a rendered map checked texel by
// texel against its float twin (within half a step, and every texel on the grid).
TEST(ShadowConventions, DepthFormatRoundsToTheUnormGrid) {
  const double q16 = 1.0 / 65535.0;
  EXPECT_EQ(stored_window_depth(0.3f, ShadowDepthFormat::Depth32f), 0.3f);
  EXPECT_EQ(stored_window_depth(0.3f, ShadowDepthFormat::Depth16), float(19661.0 * q16));  // 0.3f * 65535 = 19660.5008 -> 19661
  EXPECT_EQ(stored_window_depth(1.5f, ShadowDepthFormat::Depth16), 1.0f);
  EXPECT_EQ(stored_window_depth(-0.1f, ShadowDepthFormat::Depth24), 0.0f);
  EXPECT_DOUBLE_EQ(depth_quantum(ShadowDepthFormat::Depth24), 1.0 / 16777215.0);
  const Scene s = plane_under_spot();
  VctSettings f32, f16;
  f32.shadow_map_size = f16.shadow_map_size = 32;
  f16.shadow_depth_format = ShadowDepthFormat::Depth16;
  const Image a = render_shadow_maps(s, f32)[0].depth, b = render_shadow_maps(s, f16)[0].depth;
  ASSERT_EQ(a.data.size(), b.data.size());
  size_t moved = 0;
  for (size_t i = 0; i < a.data.size(); ++i) {
    EXPECT_LE(std::abs(double(a.data[i]) - double(b.data[i])), 0.5 * q16 + 1e-9) << i;
    // On the grid: the float nearest to k / 65535 for an integer k.
    const double steps = std::round(double(b.data[i]) / q16);
    EXPECT_EQ(b.data[i], float(steps * q16)) << i;
    moved += a.data[i] != b.data[i];
  }
  EXPECT_GT(moved, a.data.size() / 2);  // not vacuous: most texels are off the grid in float
}
}  // namespace
}  // namespace vct
