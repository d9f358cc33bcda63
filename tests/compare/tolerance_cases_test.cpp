// The tolerance cases of docs/compare.md, "Ties are admissible values" and "Required stages":
// each test is a fault the earlier rules let through (or blamed on the wrong stage), built by
// hand so that the before/after difference is the rule itself.
#include <gtest/gtest.h>

#include "compare/stage_compare.h"
#include "compare/tolerance.h"
#include "find_verdict.h"

namespace vct::cmp {
namespace {

using test::find;

// A lit floor (0.5) with a one-pixel specular highlight (6.35) at (20, 20): its neighbours are
// 12x darker, so the edge map flags it and the old rule counted any value there as a tie.
// Stripes elsewhere (equal on both sides) make the edge pixels many, as in a real frame.
Image highlight_scene() {
  Image img(64, 64, 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) img.set_rgb(x, y, vec3(x < 32 ? 0.5f : (x / 2) % 2 ? 0.8f : 0.1f));
  img.set_rgb(20, 20, vec3(6.35f));
  return img;
}

TEST(ToleranceCases, AValueBrighterThanAnyNeighbourIsNoTie) {
  // A textured G-buffer value 19 % too bright where the reference has a one-texel peak: no
  // neighbour of the reference has it, so no coverage or filtering tie can give it.
  const Image ref = highlight_scene();
  Image test = ref;
  test.set_rgb(20, 20, vec3(7.58f));
  const StageVerdict v = compare_image_stage("gbuffer.emission", ref, test, nullptr, CompareOptions{});
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
  EXPECT_EQ(v.extra.at("inadmissible").get<size_t>(), 1u);
  // A value of one of its neighbours is a tie (warn).
  test.set_rgb(20, 20, vec3(0.5f));
  EXPECT_EQ(compare_image_stage("gbuffer.emission", ref, test, nullptr, CompareOptions{}).verdict, Verdict::Warn);
}

TEST(ToleranceCases, BareShadingImagesKeepTheCountedAllowance) {
  // Judged as bare images (no re-shading on the test's own inputs, hence no range), image.direct's
  // bound does not carry its G-buffer inputs' texture freedom (demo_room at 128^2 shows a lit,
  // normal-mapped edge pixel 2.5 % above the 2^-6 bound), so its ties are still counted: the same
  // 19 % highlight only warns here. `vct validate` and `vct compare --scene` judge it on the
  // test's own G-buffer and shadow maps, where it fails (shading_on_own_inputs_test.cpp).
  const Image ref = highlight_scene();
  Image test = ref;
  test.set_rgb(20, 20, vec3(7.58f));
  const StageVerdict v = compare_image_stage("image.direct", ref, test, nullptr, CompareOptions{});
  EXPECT_EQ(v.verdict, Verdict::Warn) << v.note;
}

// A G-buffer whose emission attachment was never written: a small emitter (3x3 texels) reads 0
// in the test. Many edges elsewhere (stripes, equal on both sides) keep its share of the edge
// pixels and of all pixels under the old allowances.
TEST(ToleranceCases, ALostEmitterIsNoTieHoweverSmall) {
  Image ref(128, 128, 3);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) ref.set_rgb(x, y, vec3((x / 2) % 2 ? 0.8f : 0.1f));
  for (int y = 60; y < 63; ++y)
    for (int x = 60; x < 63; ++x) ref.set_rgb(x, y, vec3(4.0f));
  Image test = ref;
  for (int y = 60; y < 63; ++y)
    for (int x = 60; x < 63; ++x) test.set_rgb(x, y, vec3(0.0f));
  const StageVerdict v = compare_image_stage("gbuffer.emission", ref, test, nullptr, CompareOptions{});
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
  // The centre texel's whole neighbourhood is 4.0: 0 is no value a tie could give there.
  EXPECT_GE(v.extra.at("inadmissible").get<size_t>(), 1u);
}

StageSet mip_set(int levels) {
  StageSet s;
  s.backend = "test";
  s.storage = "rgba16f";
  s.reduction = "fixed_point";
  s.volumes["voxel.radiance"] = Volume(16, 16, 16, 4);
  for (int l = 1; l < levels; ++l) s.volumes["mip.iso." + std::to_string(l)] = Volume(16 >> l, 16 >> l, 16 >> l, 4);
  return s;
}

TEST(ToleranceCases, AMipChainThatStopsShortFails) {
  const StageSet ref = mip_set(5);   // 16^3 down to 1^3: levels 1..4
  const StageSet test = mip_set(4);  // one level too few
  const Report r = compare_stage_sets(ref, test);
  EXPECT_EQ(find(r, "mip.iso.4").verdict, Verdict::Fail);
  EXPECT_EQ(r.first_failing(), "mip.iso.4");
  // A stage family the test does not produce at all stays "missing" (an engine dumps what it can).
  StageSet bare = test;
  for (int l = 1; l < 4; ++l) bare.volumes.erase("mip.iso." + std::to_string(l));
  EXPECT_EQ(find(compare_stage_sets(ref, bare), "mip.iso.4").verdict, Verdict::Missing);
}

// A reference without voxels (an engine's set given as the reference) against a test with them:
// the voxel stages are missing, and nothing reads the absent volume (it threw map::at before).
TEST(ToleranceCases, VoxelsOnTheTestSideOnlyAreMissingNotACrash) {
  StageSet ref = mip_set(3);
  ref.volumes.erase("voxel.radiance");
  const StageSet test = mip_set(3);
  Report r;
  ASSERT_NO_THROW(r = compare_stage_sets(ref, test));
  EXPECT_EQ(find(r, "voxel.radiance").verdict, Verdict::Missing);
  EXPECT_EQ(find(r, "voxel.occupancy").verdict, Verdict::Missing);
  EXPECT_EQ(find(r, "mip.iso.1").verdict, Verdict::Missing);
}

TEST(ToleranceCases, LightInTransparentVoxelsIsJudged) {
  StageSet ref = mip_set(1);
  ref.volumes["voxel.radiance"].set_rgba(3, 4, 5, vec4(0.6f, 0.3f, 0.1f, 0.0f));  // particle light, opacity 0
  StageSet test = mip_set(1);  // the particles' light lost
  const Report r = compare_stage_sets(ref, test);
  const StageVerdict& v = find(r, "voxel.radiance");
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
  ASSERT_TRUE(v.extra.contains("transparent_lit")) << v.note;
  EXPECT_EQ(v.extra.at("transparent_lit").get<size_t>(), 1u);
}

TEST(ToleranceCases, SoftShadowDirectLightIsJudgedAfterTheMips) {
  StageSet a = mip_set(3);
  a.images["image.direct"] = Image(4, 4, 3);
  a.images["image.indirect_diffuse"] = Image(4, 4, 3);
  const auto order = [](const std::vector<std::string>& o, const std::string& s) {
    return std::find(o.begin(), o.end(), s) - o.begin();
  };
  std::vector<std::string> o = pipeline_order(a, a);
  EXPECT_LT(order(o, "image.direct"), order(o, "voxel.radiance"));  // shadow maps: before the voxels
  EXPECT_FALSE(is_cone_traced("image.direct", false));
  a.settings = {{"soft_shadows", true}};
  o = pipeline_order(a, a);
  EXPECT_GT(order(o, "image.direct"), order(o, "mip.iso.2"));  // cones through the mips: after them
  EXPECT_LT(order(o, "image.direct"), order(o, "image.indirect_diffuse"));
  EXPECT_TRUE(is_cone_traced("image.direct", true));  // and re-judged on the test's own mips
}

}  // namespace
}  // namespace vct::cmp
