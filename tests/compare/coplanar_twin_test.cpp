// Coplanar twins (issue 34's false-alarm hunt, scenes/regressions/seed-76-small and seed-86-small):
// two surfaces on one plane tie in depth at every pixel they share, so a correct GL may show either
// (depth ties, freedoms/raster_alternatives.h). A textured twin it shows is looked up at its own
// snapped sample and any admissible LOD, so its albedo may lie anywhere within its own texture
// slack (freedoms/gbuffer_ties.cpp, widen_by_texture_slack): the range carries that slack, and a
// value beyond it still fails.
#include <cmath>
#include <gtest/gtest.h>
#include <string>

#include "compare/stage_compare.h"
#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/texture_slack.h"
#include "stage_test_scene.h"
#include "stages/gbuffer.h"

namespace vct::cmp {
namespace {

constexpr int kSize = 16;

int channel(const Image& im, const std::string& name) {
  for (size_t c = 0; c < im.channel_names.size(); ++c)
    if (im.channel_names[c] == name) return int(c);
  return -1;
}

// Camera at the origin looking down -z (yfov 1 rad): at z = -2 the view spans +-1.0926.
void look_down_z(Scene& s) {
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
}

// The twin: a quad on z = -2 wider than the view, shifted by 0.3 in x (its diagonal elsewhere),
// with a 2x1 checkerboard (0, 255) repeated 64 times along u = (x + 2) / 4 (one level: the
// minified bilinear wave of texture_slack_test.cpp, slack 2^-8 rho = 0.0171 away from its kinks).
void add_textured_twin(Scene& s) {
  const uint32_t m = test::add_material(s, vec3(1.0f));
  const size_t first = s.positions.size();
  test::add_quad(s, {-1.7f, -2, -2}, {2.3f, -2, -2}, {2.3f, 2, -2}, {-1.7f, 2, -2}, {0, 0, 1}, m);
  for (size_t i = first; i < s.positions.size(); ++i) s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, 0.5f);
  Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255};
  s.textures.push_back(t);
  s.materials[m].base_color_texture.texture = int(s.textures.size() - 1);
  s.materials[m].base_color_texture.transform.scale = vec2(64.0f, 1.0f);
}

GBuffer render(Scene s) {
  look_down_z(s);
  s.volume = fit_volume(s.bounds);
  VctSettings st;
  st.width = st.height = kSize;
  return render_gbuffer_with_freedoms(s, st);
}

struct TwinViews {
  GBuffer both;  // an untextured green quad drawn first, then its coplanar textured twin
  GBuffer twin;  // the twin alone: its own values and texture slack at every pixel
};

TwinViews twin_views() {
  Scene both;
  const uint32_t green = test::add_material(both, vec3(0.1f, 0.8f, 0.1f));
  test::add_quad(both, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, green);
  add_textured_twin(both);
  Scene alone;
  add_textured_twin(alone);
  return {render(both), render(alone)};
}

TEST(CoplanarTwin, TheTwinsAlbedoIsAdmittedWithinItsOwnTextureSlack) {
  const TwinViews v = twin_views();
  const int lo = channel(v.both.tie_range, "albedo.0.lo"), hi = channel(v.both.tie_range, "albedo.0.hi");
  ASSERT_GE(lo, 0);
  int checked = 0;
  for (int row = 0; row < kSize; ++row)
    for (int x = 0; x < kSize; ++x) {
      // Equal depths (every vertex at z = -2): GL_LESS keeps the first, the green quad.
      ASSERT_FLOAT_EQ(v.both.albedo.at(x, row, 1), 0.8f) << x << "," << row;
      const float twin = v.twin.albedo.at(x, row, 0), slack = v.twin.texture_slack.at(x, row, kSlackAlbedo);
      if (slack < 0.01f) continue;  // near a kink of the wave
      ++checked;
      EXPECT_LE(v.both.tie_range.at(x, row, lo), twin - slack + 1e-6f) << x << "," << row;
      EXPECT_GE(v.both.tie_range.at(x, row, hi), twin + slack - 1e-6f) << x << "," << row;
    }
  EXPECT_GT(checked, kSize * kSize / 2);
}

TEST(CoplanarTwin, OnlyTheTwinsSlackIsAdmittedNotBeyond) {
  const TwinViews v = twin_views();
  // A pixel whose twin value lies on the wave's slope, well inside (0, 1), with a full slack.
  int px = -1, prow = -1;
  for (int row = 4; row < kSize - 4 && px < 0; ++row)
    for (int x = 4; x < kSize - 4 && px < 0; ++x) {
      const float twin = v.twin.albedo.at(x, row, 0), slack = v.twin.texture_slack.at(x, row, kSlackAlbedo);
      if (slack > 0.015f && twin > 0.2f && twin < 0.8f) px = x, prow = row;
    }
  ASSERT_GE(px, 0);
  const float twin = v.twin.albedo.at(px, prow, 0), slack = v.twin.texture_slack.at(px, prow, kSlackAlbedo);
  const auto gl_showing = [&](float grey) {
    Image test = v.both.albedo;
    test.set_rgb(px, prow, vec3(grey));
    return test;
  };
  CompareOptions opt;
  const Image* range = &v.both.tie_range;
  // The twin's own value at the centre: a depth tie (admitted before the slack was carried, too).
  const StageVerdict at_centre =
      compare_image_stage("gbuffer.albedo", v.both.albedo, gl_showing(twin), nullptr, opt, nullptr, nullptr, range);
  EXPECT_EQ(at_centre.verdict, Verdict::Warn) << at_centre.note;
  // 0.95 of its slack away (0.016: beyond the green pixel's bound 2^-7 + 2^-7 |range|, about 0.012):
  // the twin looked up at a shifted sample or another LOD, admitted only through its slack.
  const StageVerdict in_slack = compare_image_stage("gbuffer.albedo", v.both.albedo, gl_showing(twin + 0.95f * slack),
                                                    nullptr, opt, nullptr, nullptr, range);
  EXPECT_EQ(in_slack.verdict, Verdict::Warn) << in_slack.note;
  EXPECT_EQ(in_slack.extra.at("raster_alternatives").get<size_t>(), 1u);
  // Beyond the slack plus the bound (2^-7 + 2^-7 of the range's top, < 0.016): no GL shows it.
  EXPECT_EQ(compare_image_stage("gbuffer.albedo", v.both.albedo, gl_showing(twin + slack + 0.02f), nullptr, opt,
                                nullptr, nullptr, range)
                .verdict,
            Verdict::Fail);
  EXPECT_EQ(compare_image_stage("gbuffer.albedo", v.both.albedo, gl_showing(twin - slack - 0.02f), nullptr, opt,
                                nullptr, nullptr, range)
                .verdict,
            Verdict::Fail);
}

// Three surfaces tied in depth at one centre (hunt seed 2717, scenes/regressions/seed-2717-small: a
// plane, its coplanar twin and a sphere crossing the plane): a green quad on z = -2, its red twin
// 10^-6 behind it (1.3e-7 in window depth, within the two flat planes' margins 2 x 2^-22), and a
// blue quad tilted 45 degrees that crosses z = -2 on the line the centres of pixel column 10 see.
// On that column all three tie: each one's depth minus its margin reaches the smallest depth plus
// margin (the green's). The tilted quad's margin (2^-8 of its steep slope) makes its depth minus
// margin the smallest there, so the nearest-key rule found it alone, and the twin GL may show was
// "not among the alternatives". One column left the tilted quad is 1/2^8 x 256 = a whole pixel's
// slope in front: nothing ties there.
constexpr float kCrossingColumn = 10;

float column_x(float col, float depth) {
  return (col + 0.5f - 0.5f * float(kSize)) * 2.0f * std::tan(0.5f) * depth / float(kSize);
}

GBuffer crossing_view() {
  Scene s;
  const uint32_t green = test::add_material(s, vec3(0.1f, 0.8f, 0.1f));
  const uint32_t red = test::add_material(s, vec3(0.9f, 0.1f, 0.1f));
  const uint32_t blue = test::add_material(s, vec3(0.1f, 0.2f, 0.9f));
  const uint32_t dark = test::add_material(s, vec3(0.02f));
  test::add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, green);
  const float twin = -2.000001f;
  test::add_quad(s, {-2, -2, twin}, {2, -2, twin}, {2, 2, twin}, {-2, 2, twin}, {0, 0, 1}, red);
  const float e = column_x(kCrossingColumn, 2.0f);
  test::add_quad(s, {e - 1, -2, -1}, {e + 1, -2, -3}, {e + 1, 2, -3}, {e - 1, 2, -1}, glm::normalize(vec3(1, 0, 1)),
                 blue);
  // 1 mm behind the quad (1.3e-4 in window depth, far beyond every margin): never in front.
  test::add_quad(s, {-2, -2, -2.001f}, {2, -2, -2.001f}, {2, 2, -2.001f}, {-2, 2, -2.001f}, {0, 0, 1}, dark);
  return render(s);
}

TEST(CoplanarTwin, EverySurfaceTiedInDepthIsAdmittedNotOnlyTheNearest) {
  const GBuffer g = crossing_view();
  const int r_lo = channel(g.tie_range, "albedo.0.lo"), r_hi = channel(g.tie_range, "albedo.0.hi");
  ASSERT_GE(r_lo, 0);
  const int x = int(kCrossingColumn);
  for (int row = 2; row < kSize - 2; ++row) {
    // The reference shows the green quad or the blue one on the crossing column (their depths at
    // the centre agree within the snap), never the twin behind.
    ASSERT_NE(g.albedo.at(x, row, 0), 0.9f) << row;
    EXPECT_FLOAT_EQ(g.tie_range.at(x, row, r_hi), 0.9f) << row;  // the red twin: tied too
    EXPECT_FLOAT_EQ(g.tie_range.at(x, row, r_lo), 0.1f) << row;  // not the dark quad 1 mm behind
    // One column left the blue quad is in front by far more than the margins: only blue.
    EXPECT_FLOAT_EQ(g.tie_range.at(x - 1, row, r_lo), 0.1f) << row;
    EXPECT_FLOAT_EQ(g.tie_range.at(x - 1, row, r_hi), 0.1f) << row;
  }
}

TEST(CoplanarTwin, TheTwinOnTheCrossingIsAdmittedAndASurfaceBeyondTheMarginsFails) {
  const GBuffer g = crossing_view();
  const int x = int(kCrossingColumn), row = kSize / 2;
  const auto gl_showing = [&](int px, vec3 albedo) {
    Image test = g.albedo;
    test.set_rgb(px, row, albedo);
    return test;
  };
  CompareOptions opt;
  const vec3 red(0.9f, 0.1f, 0.1f);
  // GL keeps the twin at the crossing (hunt seed 2717's pixel (20, 18)): a depth tie.
  const StageVerdict twin =
      compare_image_stage("gbuffer.albedo", g.albedo, gl_showing(x, red), nullptr, opt, nullptr, nullptr, &g.tie_range);
  EXPECT_EQ(twin.verdict, Verdict::Warn) << twin.note;
  EXPECT_EQ(twin.extra.at("raster_alternatives").get<size_t>(), 1u);
  // The twin one column left, where the blue quad is a pixel's slope in front: no GL shows it.
  EXPECT_EQ(compare_image_stage("gbuffer.albedo", g.albedo, gl_showing(x - 1, red), nullptr, opt, nullptr, nullptr,
                                &g.tie_range)
                .verdict,
            Verdict::Fail);
  // The quad 1 mm behind, at the crossing: beyond every margin, no GL shows it.
  EXPECT_EQ(compare_image_stage("gbuffer.albedo", g.albedo, gl_showing(x, vec3(0.02f)), nullptr, opt, nullptr, nullptr,
                                &g.tie_range)
                .verdict,
            Verdict::Fail);
}

}  // namespace
}  // namespace vct::cmp
