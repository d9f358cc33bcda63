// image.direct and image.emission judged on the test's own G-buffer and shadow maps (docs/compare.md,
// "Shading stages on the test's own inputs"; issue 13 case 2): the reference re-shaded on its own
// frame gives its own bytes, every tap a correct lookup may flip lies in the reference's range,
// and a value beyond the bound outside that range fails at once, whatever the count.
#include <gtest/gtest.h>
#include <random>

#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "find_verdict.h"
#include "freedoms/direct_ties.h"
#include "freedoms/shadow_ties.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"
#include "stages/shadow_map.h"

namespace vct::cmp {
namespace {

using test::find;

Settings small() {
  Settings s;
  s.vct.width = s.vct.height = 32;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  return s;
}

// An orthographic map over [-1, 1]^3 (NDC = world), 4 x 4 texels; texel (x, y) (y up) stores
// depth[y][x]. One tap (pcf_kernel 1), nearest compare, bias 0.
ShadowMap hand_map(const float (&depth)[4][4]) {
  ShadowMap m;
  m.view_proj = mat4(1.0f);
  m.depth = Image(4, 4, 1);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) m.depth.at(x, 3 - y, 0) = depth[y][x];
  return m;
}

VctSettings one_tap() {
  VctSettings s;
  s.pcf_kernel = 1;
  s.shadow_bias = 0.0f;
  return s;
}

Light spot() {
  Light l;
  l.kind = LightKind::Spot;
  return l;
}

TEST(ShadowTies, AFarTapHasNoFreedomAndATapOnTheStoredDepthMayFlip) {
  const float d[4][4] = {{0.5f, 0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f, 0.5f}};
  const ShadowMap m = hand_map(d);
  const VctSettings s = one_tap();
  // Window depth z = ndc * 0.5 + 0.5: ndc 0.2 -> 0.6 (behind 0.5: shadowed), -0.2 -> 0.4 (lit).
  VisibilityRange r = light_visibility_range(m, spot(), vec3(0.1f, 0.1f, 0.2f), s);
  EXPECT_EQ(r.lo, 0.0f);
  EXPECT_EQ(r.hi, 0.0f);
  r = light_visibility_range(m, spot(), vec3(0.1f, 0.1f, -0.2f), s);
  EXPECT_EQ(r.lo, 1.0f);
  EXPECT_EQ(r.hi, 1.0f);
  // ndc 0 -> z = 0.5 exactly the stored depth: lit here (z <= stored), shadowed one ulp further.
  r = light_visibility_range(m, spot(), vec3(0.1f, 0.1f, 0.0f), s);
  EXPECT_EQ(shadow_visibility(m, vec3(0.1f, 0.1f, 0.0f), s), 1.0f);
  EXPECT_EQ(r.lo, 0.0f);
  EXPECT_EQ(r.hi, 1.0f);
  // The margin is a few ulps, not a fudge: 2^-16 behind the stored depth is surely shadowed.
  r = light_visibility_range(m, spot(), vec3(0.1f, 0.1f, std::ldexp(1.0f, -15)), s);
  EXPECT_EQ(r.hi, 0.0f);
}

TEST(ShadowTies, ATapOnATexelEdgeMayReadEitherTexel) {
  // Texel column 2 is a wall (0.1) in front of the point, column 1 open (1.0).
  float d[4][4];
  for (auto& row : d)
    for (int x = 0; x < 4; ++x) row[x] = x >= 2 ? 0.1f : 1.0f;
  const ShadowMap m = hand_map(d);
  const VctSettings s = one_tap();
  // u = (ndc * 0.5 + 0.5) * 4 = 2 exactly at ndc 0: the tap floors to texel 2 (shadowed) here,
  // to texel 1 (lit) one ulp to the left.
  VisibilityRange r = light_visibility_range(m, spot(), vec3(0.0f, 0.1f, 0.0f), s);
  EXPECT_EQ(r.lo, 0.0f);
  EXPECT_EQ(r.hi, 1.0f);
  // A quarter texel away either side: no freedom.
  r = light_visibility_range(m, spot(), vec3(-0.125f, 0.1f, 0.0f), s);
  EXPECT_EQ(r.lo, 1.0f);
  r = light_visibility_range(m, spot(), vec3(0.125f, 0.1f, 0.0f), s);
  EXPECT_EQ(r.hi, 0.0f);
}

// On real maps (the built-in box's spot, 3x3 PCF) the reference's own visibility always lies in
// its range, and the range is a point almost everywhere.
TEST(ShadowTies, TheReferencesVisibilityLiesInItsRangeAndTheRangeIsRarelyOpen) {
  const Scene scene = load_scene("");
  Settings s = small();
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, s.vct);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  size_t open = 0, n = 20000;
  for (size_t k = 0; k < n; ++k) {
    const vec3 p = scene.volume.to_world(vec3(u(rng), u(rng), u(rng)));
    const float v = light_visibility(maps[0], scene.lights[0], p, s.vct);
    const VisibilityRange r = light_visibility_range(maps[0], scene.lights[0], p, s.vct);
    ASSERT_LE(r.lo, v);
    ASSERT_GE(r.hi, v);
    open += r.lo < r.hi;
  }
  EXPECT_LT(open, n / 100) << open << " of " << n << " random points have a tap that may flip";
}

// Reading the test's own inputs: the reference re-shaded on its own frame gives its own direct
// light bit for bit, and its range contains it.
TEST(ShadingOnOwnInputs, TheReferenceReShadedOnItsOwnFrameGivesItsOwnDirectLight) {
  const Scene scene = load_scene("");
  const Settings s = small();
  const FrameResult ref = render_ref_frame(scene, s);
  const FrameResult again = reference_on_test_inputs(scene, ref, s.vct);
  EXPECT_EQ(again.images.direct.data, ref.images.direct.data);
  EXPECT_EQ(again.images.emission.data, ref.images.emission.data);
  const Image& range = again.gbuffer.tie_range;
  ASSERT_EQ(range.channels, 12);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        ASSERT_LE(range.at(x, y, 2 * c), ref.images.direct.at(x, y, c));
        ASSERT_GE(range.at(x, y, 2 * c + 1), ref.images.direct.at(x, y, c));
      }
  // Without the test's shadow maps direct light is not re-judged (missing: the end-to-end verdict stands).
  FrameResult no_maps = ref;
  no_maps.shadow_maps.clear();
  EXPECT_TRUE(reference_on_test_inputs(scene, no_maps, s.vct).images.direct.empty());
}

// The report `vct validate` gives: end to end, then the cone and shading stages on the test's inputs.
Report judged(const Scene& scene, const FrameResult& ref, const FrameResult& test, const VctSettings& s) {
  const StageSet ts = stage_set_from_frame(test, s);
  Report rep = compare_stage_sets(stage_set_from_frame(ref, s), ts);
  apply_isolated_verdicts(rep, compare_stage_sets(stage_set_from_frame(reference_on_test_inputs(scene, test, s), s), ts),
                          s.soft_shadows);
  return rep;
}

// Issue 13 case 2: the brightest direct pixel 19 % too bright (a Fresnel exponent 4 in a
// one-pixel highlight). End to end one pixel is within the counted share (warn); on the test's
// own inputs it is beyond the bound and outside the PCF range: FAIL. A correct frame passes.
TEST(ShadingOnOwnInputs, AOnePixelHighlightNineteenPercentTooBrightFails) {
  const Scene scene = load_scene("");
  const Settings s = small();
  const FrameResult ref = render_ref_frame(scene, s);
  EXPECT_EQ(find(judged(scene, ref, ref, s.vct), "image.direct").verdict, Verdict::Pass);
  FrameResult test = ref;
  Image& d = test.images.direct;
  int bx = 0, by = 0;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x)
      if (d.at(x, y, 0) + d.at(x, y, 1) + d.at(x, y, 2) > d.at(bx, by, 0) + d.at(bx, by, 1) + d.at(bx, by, 2))
        bx = x, by = y;
  d.set_rgb(bx, by, d.rgb(bx, by) * 1.19f);
  const StageVerdict e2e = find(compare_stage_sets(stage_set_from_frame(ref, s.vct), stage_set_from_frame(test, s.vct)),
                                "image.direct");
  EXPECT_EQ(e2e.verdict, Verdict::Warn) << e2e.note;  // the counted share (bare images keep it)
  const StageVerdict v = find(judged(scene, ref, test, s.vct), "image.direct");
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
  EXPECT_EQ(v.extra.at("inadmissible").get<size_t>(), 1u) << v.note;
  EXPECT_NE(v.note.find("on the test's own G-buffer and shadow maps"), std::string::npos) << v.note;
}

// The same on image.emission: the G-buffer's emission added at one pixel 19 % too bright.
TEST(ShadingOnOwnInputs, EmissionAddedWrongAtOnePixelFails) {
  const Scene scene = load_scene("");
  const Settings s = small();
  const FrameResult ref = render_ref_frame(scene, s);
  FrameResult test = ref;
  Image& e = test.images.emission;
  int bx = 0, by = 0;
  for (int y = 0; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x)
      if (e.at(x, y, 0) > e.at(bx, by, 0)) bx = x, by = y;
  ASSERT_GT(e.at(bx, by, 0), 0.0f);
  e.set_rgb(bx, by, e.rgb(bx, by) * 1.19f);
  EXPECT_EQ(find(judged(scene, ref, ref, s.vct), "image.emission").verdict, Verdict::Pass);
  EXPECT_EQ(find(judged(scene, ref, test, s.vct), "image.emission").verdict, Verdict::Fail);
}

// A pixel whose light may legitimately differ by a PCF tap: the test shows the visibility one tap
// darker where the reference's range allows it (pass as a tie, counted in raster_alternatives),
// and the same change at a pixel without freedom fails.
TEST(ShadingOnOwnInputs, ATapTheRangeAllowsIsATieAndNowhereElse) {
  const Scene scene = load_scene("");
  const Settings s = small();
  const FrameResult ref = render_ref_frame(scene, s);
  const FrameResult on_ref = reference_on_test_inputs(scene, ref, s.vct);
  const Image& range = on_ref.gbuffer.tie_range;
  // Make the range at one pixel open by hand (a lit pixel), and move the test to its low end.
  int px = -1, py = -1;
  for (int y = 0; y < 32 && px < 0; ++y)
    for (int x = 0; x < 32 && px < 0; ++x)
      if (ref.images.direct.at(x, y, 0) > 0.05f) px = x, py = y;
  ASSERT_GE(px, 0);
  Image open = range;
  for (int c = 0; c < 3; ++c) open.at(px, py, 2 * c) = 0.5f * ref.images.direct.at(px, py, c);
  FrameResult test = ref;
  test.images.direct.set_rgb(px, py, 0.5f * ref.images.direct.rgb(px, py));
  FrameResult r = on_ref;
  const StageSet ts = stage_set_from_frame(test, s.vct);
  r.gbuffer.tie_range = open;
  StageVerdict v = find(compare_stage_sets(stage_set_from_frame(r, s.vct), ts), "image.direct");
  EXPECT_EQ(v.verdict, Verdict::Warn) << v.note;
  EXPECT_EQ(v.extra.at("raster_alternatives").get<size_t>(), 1u);
  r.gbuffer.tie_range = range;  // the range as computed: no freedom there
  v = find(compare_stage_sets(stage_set_from_frame(r, s.vct), ts), "image.direct");
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
}

}  // namespace
}  // namespace vct::cmp
