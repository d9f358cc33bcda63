// The declared display transform (manifest conventions.display, compare/display_transform.h):
// hand values of the transform and of the bound it carries, the manifest keys, and the judgement
// on the reference's own final written as an engine would (Reinhard, gamma 2.2, 8 bits) -- the
// GL version of the last three is tests/gl/gl_display_transform_test.cpp.
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

#include "compare/stage_compare.h"
#include "core/error.h"
#include "display_fixtures.h"
#include "freedoms/reference_frame.h"
#include "scene/gltf_loader.h"

namespace vct::cmp {
namespace {

TEST(DisplayTransform, HandValues) {
  const DisplayTransform d = reinhard_22_8();
  // Reinhard 1 -> 0.5; 0.5^(1/2.2) = 0.729740; 8 bits: 0.729740 x 255 = 186.08 -> 186 / 255.
  EXPECT_NEAR(d.apply(1.0), 0.7297400528, 1e-9);
  EXPECT_DOUBLE_EQ(d.encode(1.0), 186.0 / 255.0);
  EXPECT_DOUBLE_EQ(d.quantisation_allowance(), 1.0 / 255.0);
  // The carried bound: the transform's change over [r - b, r + b] plus one 8-bit step;
  // at r = 1, b = 0.1 the lower side is the larger (the transform is concave there):
  // 0.5^(1/2.2) - (0.9/1.9)^(1/2.2) = 0.01770 against 0.01559 above.
  EXPECT_NEAR(d.carry_bound(1.0, 0.1), std::pow(0.5, 1.0 / 2.2) - std::pow(0.9 / 1.9, 1.0 / 2.2) + 1.0 / 255.0, 1e-12);
  // Near black it stays finite where gamma's slope does not.
  EXPECT_NEAR(d.carry_bound(0.0, 1e-4), std::pow(1e-4 / (1.0 + 1e-4), 1.0 / 2.2) + 1.0 / 255.0, 1e-12);
  // ACES (Narkowicz) at 1: 2.54 / 3.16 = 0.803797.
  DisplayTransform aces;
  aces.op = ToneOperator::Aces;
  EXPECT_NEAR(aces.apply(1.0), 2.54 / 3.16, 1e-12);
  EXPECT_FALSE(DisplayTransform().declared());
}

TEST(DisplayTransform, ManifestKeys) {
  const Conventions c = read_conventions(
      "m.json", nlohmann::json{{"display", {{"operator", "reinhard"}, {"gamma", 2.2}, {"bits", 8}}}});
  EXPECT_EQ(c.display.op, ToneOperator::Reinhard);
  EXPECT_EQ(c.display.gamma, 2.2);
  EXPECT_EQ(c.display.bits, 8);
  EXPECT_TRUE(c.display.applies_to("image.final"));
  EXPECT_FALSE(c.display.applies_to("image.direct"));
  EXPECT_EQ(read_conventions("m.json", to_json(c)).display.bits, 8);  // round trip
  for (const nlohmann::json& bad :
       {nlohmann::json{{"operator", "filmic"}}, nlohmann::json{{"gamma", 0}}, nlohmann::json{{"bits", 17}},
        nlohmann::json{{"stages", {"gbuffer.albedo"}}}, nlohmann::json{{"gama", 2.2}}})
    EXPECT_THROW(read_conventions("m.json", nlohmann::json{{"display", bad}}), InputError) << bad.dump();
}

struct Fixture {
  Settings s;
  FrameResult frame;
  StageSet ref;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.s.vct.width = x.s.vct.height = 48;
    x.s.vct.grid = 32;
    x.s.vct.shadow_map_size = 128;
    x.frame = render_ref_frame(load_scene(""), x.s);
    x.ref = stage_set_from_frame(x.frame, x.s.vct);
    return x;
  }();
  return f;
}

// Only image.final, encoded with final + (scale - 1)(diffuse + specular terms).
StageVerdict judge(float indirect_scale, bool declare) {
  const Fixture& f = fixture();
  const FrameImages& im = f.frame.images;
  const DisplayTransform d = reinhard_22_8();
  Image out = im.final_image;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < std::min(out.channels, 3); ++c)
        out.at(x, y, c) = float(d.encode(double(out.at(x, y, c) + (indirect_scale - 1.0f) * (im.diffuse_term.at(x, y, c) +
                                                                                            im.specular_term.at(x, y, c)))));
  StageSet e;
  e.backend = "engine";
  e.images["image.final"] = out;
  if (declare) e.conventions.display = d;
  const Report r = compare_stage_sets(f.ref, e);
  for (const StageVerdict& v : r.stages)
    if (v.stage == "image.final") {
      std::printf("[display] scale %.1f %s: %s, %s\n", double(indirect_scale), declare ? "declared" : "undeclared",
                  to_string(v.verdict).c_str(), v.note.c_str());
      return v;
    }
  ADD_FAILURE() << "no image.final verdict";
  return {};
}

TEST(DisplayTransform, DeclaredEncodedFinalPasses) {
  const StageVerdict v = judge(1.0f, true);
  EXPECT_EQ(v.verdict, Verdict::Pass) << v.note;
  EXPECT_TRUE(v.extra.contains("display_transform"));
}

TEST(DisplayTransform, UndeclaredEncodedFinalFails) { EXPECT_EQ(judge(1.0f, false).verdict, Verdict::Fail); }

TEST(DisplayTransform, IndirectTimesOnePointThreeUnderTheDeclaredTransformFails) {
  EXPECT_EQ(judge(1.3f, true).verdict, Verdict::Fail);
}

}  // namespace
}  // namespace vct::cmp
