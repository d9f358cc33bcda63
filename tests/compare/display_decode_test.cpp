// A display-encoded image.direct in the re-traced composite (`vct compare --scene`, issue 21): the
// engine's stored direct light is decoded through the declared transform's inverse before the
// reference adds its re-traced indirect terms (compare/isolated_stages.h decode_display_direct).
// Hand values of the inverse, the one-step property the bound rests on, and the judgement of a
// tone-mapped 8-bit frame on its own inputs in both directions.
#include <cmath>
#include <gtest/gtest.h>

#include "compare/isolated_stages.h"
#include "compare/stage_set.h"
#include "display_fixtures.h"
#include "find_verdict.h"
#include "freedoms/reference_frame.h"
#include "scene/gltf_loader.h"

namespace vct::cmp {
namespace {

// The image stages these tests declare display-encoded.
const std::vector<std::string> kEncodedStages = {"image.direct", "image.indirect_diffuse",
                                                 "image.indirect_specular", "image.final"};

TEST(DisplayDecode, HandValuesOfTheInverse) {
  const DisplayTransform d = reinhard_22_8(kEncodedStages);
  // 0.5^2.2 = 0.2176376; x / (1 + x) = 0.2176376 -> x = 0.2176376 / 0.7823624 = 0.2781795.
  EXPECT_NEAR(d.decode(0.5), 0.2781795, 1e-6);
  EXPECT_NEAR(d.apply(d.decode(0.5)), 0.5, 1e-12);
  EXPECT_EQ(d.decode(0.0), 0.0);
  // A stored 1 is Reinhard's value half a step below 1: y = 1 - 0.5/255, x = y / (1 - y) = 509.
  EXPECT_NEAR(d.decode(1.0), 509.0, 1e-6);
  DisplayTransform exposed = d;
  exposed.exposure = 2.0;  // the linear value before the exposure: half
  EXPECT_NEAR(exposed.decode(0.5), 0.2781795 / 2.0, 1e-6);
  DisplayTransform plain;  // operator none, gamma 2, float: y^2, above 1 kept
  plain.gamma = 2.0;
  EXPECT_DOUBLE_EQ(plain.decode(1.5), 2.25);
  EXPECT_TRUE(d.decodable());
  EXPECT_TRUE(plain.decodable());
  DisplayTransform aces = d;
  aces.op = ToneOperator::Aces;  // convex toe
  EXPECT_FALSE(aces.decodable());
  DisplayTransform expand = d;
  expand.gamma = 0.5;  // y^2: convex
  EXPECT_FALSE(expand.decodable());
}

// The bound's derivation: the engine stores e within one step q of D(d) (either neighbour, GL 4.5
// §2.3.5.1); the decoded d' has D(d') = e, and D concave increasing gives
// |D(d' + r) - D(d + r)| <= |D(d') - D(d)| <= q for every r >= 0 the composite adds. Checked on a
// grid of direct values, both rounding neighbours and added light from 0 to 100.
TEST(DisplayDecode, ASumOnADecodedValueStaysWithinOneStep) {
  const DisplayTransform d = reinhard_22_8(kEncodedStages);
  const double q = d.quantisation_allowance();
  double worst = 0.0;
  for (double direct = 0.0; direct < 40.0; direct = direct * 1.07 + 1e-4)
    for (double stored : {std::floor(d.apply(direct) * 255.0) / 255.0, std::ceil(d.apply(direct) * 255.0) / 255.0})
      for (double added = 0.0; added < 100.0; added = added * 1.3 + 1e-3)
        worst = std::max(worst, std::abs(d.apply(d.decode(stored) + added) - d.apply(direct + added)));
  EXPECT_LE(worst, q * (1.0 + 1e-9));
  EXPECT_GT(worst, 0.5 * q);  // the step is the right size: half of it would not do
}

// The reference's frame written as a tone-mapping engine writes it (direct, indirect and final
// Reinhard + gamma 2.2 + 8 bits), judged with --scene's isolated re-trace on its own inputs.
struct Encoded {
  Scene scene = load_scene("");
  Settings s;
  FrameResult ref, engine;
  explicit Encoded(float final_fault = 1.0f) {
    s.vct.width = s.vct.height = 32;
    s.vct.grid = 16;
    s.vct.shadow_map_size = 128;
    ref = render_ref_frame(scene, s);
    engine = ref;
    engine.backend = "engine";
    const DisplayTransform d = reinhard_22_8(kEncodedStages);
    for (Image* img : {&engine.images.direct, &engine.images.indirect_diffuse, &engine.images.indirect_specular,
                       &engine.images.final_image})
      for (int y = 0; y < img->height; ++y)
        for (int x = 0; x < img->width; ++x)
          for (int c = 0; c < 3; ++c) {
            const double linear = img->at(x, y, c) * (img == &engine.images.final_image ? final_fault : 1.0f);
            img->at(x, y, c) = float(d.encode(linear));
          }
  }
  StageVerdict final_verdict(const DisplayTransform& declared) const {
    StageSet ref_set = stage_set_from_frame(ref, s.vct);
    StageSet test_set = stage_set_from_frame(engine, s.vct);
    test_set.conventions.display = declared;
    Report r = compare_stage_sets(ref_set, test_set);
    judge_cones_on_test_inputs(r, scene, engine, s.vct, test_set);
    return test::find(r, "image.final");
  }
};

TEST(DisplayDecode, EncodedFrameOnItsOwnInputsPassesWhenTheDirectIsDecoded) {
  const Encoded e;
  const StageVerdict v = e.final_verdict(reinhard_22_8(kEncodedStages));
  EXPECT_NE(v.verdict, Verdict::Fail) << v.note;
  EXPECT_NE(v.note.find("on the test's own voxels"), std::string::npos) << v.note;
}

TEST(DisplayDecode, DirectTakenAsLinearFails) {
  // The same frame with image.direct left out of the declared stages: its encoded values enter the
  // composite as radiance (what `--scene` did before), and image.final fails on its own inputs.
  const Encoded e;
  DisplayTransform d = reinhard_22_8(kEncodedStages);
  d.stages = {"image.indirect_diffuse", "image.indirect_specular", "image.final"};
  EXPECT_EQ(e.final_verdict(d).verdict, Verdict::Fail);
}

TEST(DisplayDecode, AFinalFaultUnderTheDecodedDirectFails) {
  const Encoded e(1.3f);  // the engine's final 1.3x too bright before its display transform
  EXPECT_EQ(e.final_verdict(reinhard_22_8(kEncodedStages)).verdict, Verdict::Fail);
}

TEST(DisplayDecode, AnUndecodableTransformKeepsTheEndToEndVerdict) {
  Encoded e;
  DisplayTransform aces = reinhard_22_8(kEncodedStages);
  aces.op = ToneOperator::Aces;
  const StageVerdict v = e.final_verdict(aces);
  EXPECT_EQ(v.note.find("on the test's own voxels"), std::string::npos) << v.note;
  EXPECT_EQ(direct_input_of(&aces), DirectInput::Undecodable);
}

}  // namespace
}  // namespace vct::cmp
