// A G-buffer pixel showing a value the reference's raster alternatives allow (the surface behind a
// silhouette that ties, the negated normal of a triangle whose facing ties) is admitted; without
// the range, or with a value outside it, the stage fails (compare/tie_range.h).
#include <gtest/gtest.h>
#include <string>

#include "compare/display_transform.h"
#include "compare/stage_compare.h"
#include "freedoms/gbuffer_ties.h"

namespace vct::cmp {
namespace {

constexpr int kSize = 8;

// The range image for one group, lo = hi = the reference everywhere.
Image own_range(const std::string& group, const Image& ref) {
  Image r(ref.width, ref.height, 2 * ref.channels);
  for (int c = 0; c < ref.channels; ++c)
    for (bool upper : {false, true}) r.channel_names.push_back(tie_range_channel_name(group, c, upper));
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x)
      for (int c = 0; c < ref.channels; ++c) r.at(x, y, 2 * c) = r.at(x, y, 2 * c + 1) = ref.at(x, y, c);
  return r;
}

// A plane seen head-on: x and y follow the pixel, z = -2.
Image plane_positions() {
  Image p(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) p.set_rgb(x, y, vec3(0.1f * float(x), -0.1f * float(y), -2.0f));
  return p;
}

TEST(RasterAlternatives, SurfaceBehindATiedSilhouetteIsAdmittedOnlyWithTheRange) {
  const Image ref = plane_positions();
  Image range = own_range("position", ref);
  // Pixel (4, 4): the reference's silhouette runs through its centre; behind it a wall at z = -4,
  // where this pixel's ray lands at twice the distance.
  const vec3 behind(0.8f, -0.8f, -4.0f);
  for (int c = 0; c < 3; ++c) {
    range.at(4, 4, 2 * c) = std::min(ref.at(4, 4, c), behind[c]);
    range.at(4, 4, 2 * c + 1) = std::max(ref.at(4, 4, c), behind[c]);
  }
  Image test = ref;
  test.set_rgb(4, 4, behind);
  CompareOptions opt;
  // Before: an interior pixel outside its 3x3 neighbourhood's range fails.
  EXPECT_EQ(compare_image_stage("gbuffer.position", ref, test, nullptr, opt).verdict, Verdict::Fail);
  // With the reference's alternatives: a value a correct GL shows there.
  const StageVerdict v = compare_image_stage("gbuffer.position", ref, test, nullptr, opt, nullptr, nullptr, &range);
  EXPECT_EQ(v.verdict, Verdict::Warn) << v.note;
  EXPECT_EQ(v.extra.at("raster_alternatives").get<size_t>(), 1u);
  // A wall at z = -5 is no alternative there.
  test.set_rgb(4, 4, vec3(0.8f, -0.8f, -5.0f));
  EXPECT_EQ(compare_image_stage("gbuffer.position", ref, test, nullptr, opt, nullptr, nullptr, &range).verdict,
            Verdict::Fail);
  // Nor is the alternative at a pixel whose range holds only the reference.
  test = ref;
  test.set_rgb(2, 2, behind);
  EXPECT_EQ(compare_image_stage("gbuffer.position", ref, test, nullptr, opt, nullptr, nullptr, &range).verdict,
            Verdict::Fail);
}

TEST(RasterAlternatives, NegatedNormalIsAdmittedWhereTheFacingTies) {
  Image ref(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ref.set_rgb(x, y, vec3(0.6f, 0.0f, 0.8f));
  Image range = own_range("normal", ref);
  for (int c = 0; c < 3; ++c) {  // (3, 5): an edge-on triangle, either facing
    range.at(3, 5, 2 * c) = -std::abs(ref.at(3, 5, c));
    range.at(3, 5, 2 * c + 1) = std::abs(ref.at(3, 5, c));
  }
  Image test = ref;
  test.set_rgb(3, 5, vec3(-0.6f, 0.0f, -0.8f));
  CompareOptions opt;
  EXPECT_EQ(compare_image_stage("gbuffer.normal", ref, test, nullptr, opt).verdict, Verdict::Fail);
  EXPECT_EQ(compare_image_stage("gbuffer.normal", ref, test, nullptr, opt, nullptr, nullptr, &range).verdict,
            Verdict::Warn);
  // The range belongs to the normal: position's stage finds no channels of its own in it.
  EXPECT_EQ(compare_image_stage("gbuffer.position", ref, test, nullptr, opt, nullptr, nullptr, &range).verdict,
            Verdict::Fail);
}

TEST(RasterAlternatives, WithTheRangeANeighboursValueIsNoLongerATie) {
  // Two flat halves (0.2 | 0.7) of a 64^2 image meeting between columns 31 and 32: pixel
  // (31, 10) showing its right neighbour's value is an edge tie for the neighbourhood rule (one
  // of 128 edge pixels, inside 2.5 %), but not a value the reference's raster alternatives allow
  // there (no edge passes within 2^-8 pixel of its centre): with the range it fails.
  Image ref(64, 64, 1);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) ref.at(x, y, 0) = x < 32 ? 0.2f : 0.7f;
  Image test = ref;
  test.at(31, 10, 0) = 0.7f;
  CompareOptions opt;
  EXPECT_EQ(compare_image_stage("gbuffer.coverage", ref, test, nullptr, opt).verdict, Verdict::Warn);
  const Image range = own_range("coverage", ref);
  const StageVerdict v = compare_image_stage("gbuffer.coverage", ref, test, nullptr, opt, nullptr, nullptr, &range);
  EXPECT_EQ(v.verdict, Verdict::Fail);
  EXPECT_EQ(v.extra.at("inadmissible").get<size_t>(), 1u);
  // A one-pixel shift of the whole image, admissible pixel by pixel for the neighbourhood rule
  // and caught there only by the count, fails here at its first pixel.
  EXPECT_EQ(v.extra.at("allowed_edge_fraction").get<double>(), 0.0);
}

// The shading stages' ranges (a PCF tap that may flip, freedoms/direct_ties.h) hold for an engine
// that wrote its direct light display-encoded too: the range's ends carried through the declared
// transform, plus one step of the 8-bit store.
TEST(RasterAlternatives, DisplayEncodedShadingStageIsAdmittedWithinTheRangeCarriedThroughTheTransform) {
  Image ref(kSize, kSize, 3, 0.5f);
  Image range = own_range("image.direct", ref);
  for (int c = 0; c < 3; ++c) range.at(3, 3, 2 * c) = 0.1f;  // one tap shadowed on GL's side
  DisplayTransform gamma;
  gamma.gamma = 2.2;
  gamma.bits = 8;
  gamma.stages = {"image.direct"};
  const auto encoded = [&](float linear) {
    Image t(kSize, kSize, 3, float(gamma.encode(0.5)));
    t.set_rgb(3, 3, vec3(float(gamma.encode(double(linear)))));
    return t;
  };
  CompareOptions opt;
  const StageVerdict v =
      compare_image_stage("image.direct", ref, encoded(0.1f), nullptr, opt, nullptr, &gamma, &range);
  EXPECT_EQ(v.verdict, Verdict::Warn) << v.note;
  EXPECT_EQ(v.extra.at("raster_alternatives").get<size_t>(), 1u);
  // Darker than the range allows: no tie gives it.
  EXPECT_EQ(compare_image_stage("image.direct", ref, encoded(0.05f), nullptr, opt, nullptr, &gamma, &range).verdict,
            Verdict::Fail);
  // Without the tap's range the same 0.1 is no alternative either.
  const Image own = own_range("image.direct", ref);
  EXPECT_EQ(compare_image_stage("image.direct", ref, encoded(0.1f), nullptr, opt, nullptr, &gamma, &own).verdict,
            Verdict::Fail);
}

}  // namespace
}  // namespace vct::cmp
