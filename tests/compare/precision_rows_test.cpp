// Each row of the precision table (core/precision.h; docs/compare.md, "Precision table") at the
// stage or freedom producer that consumes it, on hand-made inputs, two cases per row:
//   Admits*: an element off by the stage's whole bound (the other terms plus the row's allowed
//     error) is admitted, and the bound without the row's term is smaller than that error, so
//     the case fails without the row;
//   *BeyondFails: an element off by clearly more (twice the bound, or one further quantum of the
//     row) FAILs: the reverse, a GL off by more than the allowed error still fails.
// Flat (or linear) images and volumes with every element shifted alike: no edges, so no tie rule
// and no counted share can admit what the bound does not (compare/counted_shares.h).
// Rows tested elsewhere: srgb-decode (tests/compare/srgb_decode_precision_test.cpp,
// tests/gl/gl_srgb_precision_test.cpp); attribute-extrapolation's admission in
// tests/ref/fragment_slack_test.cpp (SnapReachCoversExtrapolatedAttributes). msaa-resolve is
// carried nowhere (no stage resolves).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <gtest/gtest.h>

#include "snapped_triangle_fixture.h"
#include "../ref/stage_test_scene.h"
#include "compare/display_transform.h"
#include "compare/stage_compare.h"
#include "compare/tolerance.h"
#include "core/precision.h"
#include "find_verdict.h"
#include "freedoms/fragment_slack.h"
#include "freedoms/lod_candidates.h"
#include "freedoms/shadow_ties.h"
#include "scene/texture_lod.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"

namespace vct::cmp {
namespace {

constexpr int kSize = 16;

// Every channel of every element shifted by `d`; returns the shift as stored (float).
Image shifted(const Image& ref, double d, double* stored = nullptr) {
  Image t = ref;
  for (float& v : t.data) v = float(double(v) + d);
  if (stored) *stored = double(t.data[0]) - double(ref.data[0]);
  return t;
}

Volume shifted_rgb(const Volume& ref, double d, double* stored = nullptr) {
  Volume t = ref;
  for (size_t i = 0; i < t.data.size(); ++i)
    if (i % size_t(t.channels) < 3) t.data[i] = float(double(t.data[i]) + d);
  if (stored) *stored = double(t.data[0]) - double(ref.data[0]);
  return t;
}

// Just under the bound: the error the row admits, less a margin far above float spacing.
double just_under(double bound) { return bound * (1.0 - 0x1p-8); }

Verdict image_verdict(const std::string& stage, const Image& ref, const Image& test,
                      const DisplayTransform* display = nullptr) {
  const StageVerdict v = compare_image_stage(stage, ref, test, nullptr, CompareOptions{}, nullptr, display);
  std::printf("  %s: %s %s\n", stage.c_str(), to_string(v.verdict).c_str(), v.note.c_str());
  return v.verdict;
}

// One image row: `bound` the stage's bound at the test's pixels, `without` the same bound less
// the row's term.
void expect_image_row(const std::string& stage, const Image& ref, double bound, double without) {
  double d = 0.0;
  const Image test = shifted(ref, just_under(bound), &d);
  EXPECT_LE(d, bound);
  EXPECT_GT(d, without) << "the error must fail without the row's term";
  EXPECT_EQ(image_verdict(stage, ref, test), Verdict::Pass);
}

void expect_image_beyond_fails(const std::string& stage, const Image& ref, double bound) {
  EXPECT_EQ(image_verdict(stage, ref, shifted(ref, 2.0 * bound)), Verdict::Fail);
}

// ---- subpixel-snap: the raster stages' slope term (d32f-depth, interpolated-attribute) -------
// A depth ramp of 1/64 per pixel along x: attribute_slope = 1/64, so the bound is
// 2^-14 + 2^-8 x 2^-6 = 2^-13, half of it the snap's term.
Image depth_ramp() {
  Image img(kSize, kSize, 1);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) img.at(x, y, 0) = 0.25f + float(x) / 64.0f;
  return img;
}

TEST(PrecisionRows, SubpixelSnapAdmitsTheSlopeTerm) {
  ASSERT_EQ(image_model(ToleranceModel::Depth).slope_factor, precision(Precision::SubpixelSnap));
  const double snap_term = precision(Precision::SubpixelSnap) / 64.0;
  expect_image_row("gbuffer.depth", depth_ramp(), 0x1p-14 + snap_term, 0x1p-14);
}

TEST(PrecisionRows, SubpixelSnapBeyondFails) { expect_image_beyond_fails("gbuffer.depth", depth_ramp(), 0x1p-13); }

// ---- depth-interpolation: d32f-depth's absolute term -----------------------------------------
TEST(PrecisionRows, DepthInterpolationAdmitsItsError) {
  ASSERT_EQ(image_model(ToleranceModel::Depth).abs, precision(Precision::DepthInterpolation));
  // Flat: no slope term, so the row is the whole bound.
  expect_image_row("gbuffer.depth", Image(kSize, kSize, 1, 0.5f), precision(Precision::DepthInterpolation), 0.0);
  expect_image_row("shadow_map.0", Image(kSize, kSize, 1, 0.5f), precision(Precision::DepthInterpolation), 0.0);
}

TEST(PrecisionRows, DepthInterpolationBeyondFails) {
  expect_image_beyond_fails("gbuffer.depth", Image(kSize, kSize, 1, 0.5f), precision(Precision::DepthInterpolation));
}

// ---- depth-unorm and unorm16: a shadow map under a declared depth16 format --------------------
// Each side within one step q = 1/65535 of its float depth (either neighbour): 2q beyond the float
// bound (compare/image_judge.cpp, depth_format).
StageSet depth16_set(const Image& map) {
  StageSet s;
  s.backend = "test";
  s.settings = {{"shadow_depth_format", "depth16"}};
  s.images["shadow_map.0"] = map;
  return s;
}

Verdict shadow_map_verdict(const Image& ref, const Image& test) {
  const Report r = compare_stage_sets(depth16_set(ref), depth16_set(test));
  const StageVerdict& v = test::find(r, "shadow_map.0");
  std::printf("  shadow_map.0 (depth16): %s %s\n", to_string(v.verdict).c_str(), v.note.c_str());
  return v.verdict;
}

double depth16_bound() {
  return precision(Precision::DepthInterpolation) + precision(Precision::DepthUnorm) * precision(Precision::Unorm16);
}

TEST(PrecisionRows, DepthUnormAndUnorm16AdmitTwoSteps) {
  EXPECT_EQ(depth_quantum(ShadowDepthFormat::Depth16), precision(Precision::Unorm16));
  const Image ref(kSize, kSize, 1, 0.5f);
  double d = 0.0;
  const Image test = shifted(ref, just_under(depth16_bound()), &d);
  EXPECT_GT(d, precision(Precision::DepthInterpolation)) << "fails without the 2q term";
  EXPECT_EQ(shadow_map_verdict(ref, test), Verdict::Pass);
}

TEST(PrecisionRows, DepthUnormOneFurtherStepFails) {
  const Image ref(kSize, kSize, 1, 0.5f);
  EXPECT_EQ(shadow_map_verdict(ref, shifted(ref, depth16_bound() + 1.5 * precision(Precision::Unorm16))),
            Verdict::Fail);
}

// ---- attribute-interpolation: gbuffer.position's relative term ------------------------------
// Flat position 8: bound 1e-4 + 2^-12 x 8 (no slope).
TEST(PrecisionRows, AttributeInterpolationAdmitsItsRelativeError) {
  ASSERT_EQ(image_model(ToleranceModel::Position).rel, precision(Precision::AttributeInterpolation));
  const double bound = 1e-4 + precision(Precision::AttributeInterpolation) * 8.0;
  expect_image_row("gbuffer.position", Image(kSize, kSize, 3, 8.0f), bound, 1e-4);
}

TEST(PrecisionRows, AttributeInterpolationBeyondFails) {
  expect_image_beyond_fails("gbuffer.position", Image(kSize, kSize, 3, 8.0f),
                            1e-4 + precision(Precision::AttributeInterpolation) * 8.0);
}

// ---- attribute-extrapolation: the voxel shading slack's snap reach ---------------------------
// The admitting case is FragmentSlack.SnapReachCoversExtrapolatedAttributes (tests/ref): every
// 2^-8 snap of a quarter-voxel triangle whose centre lies outside it (barycentrics (-3, 2, 2))
// moves the interpolated point within voxel_snap_reach = 7/240 voxel, 6.5x the snap itself.
// Here the reverse: vertices off by 2^-7 (one subpixel bit fewer than the row allows) move it
// beyond the reach, so the slack does not cover such a GL.
TEST(PrecisionRows, AttributeExtrapolationBeyondTheReach) {
  Scene s;
  const uint32_t m = vct::test::add_material(s, vec3(0.8f));
  vct::test::add_triangle(s, {4.0f, 4.0f, 3.5f}, {4.25f, 4.0f, 3.5f}, {4.0f, 4.25f, 3.5f}, m);
  s.volume.origin = vec3(0.0f);
  s.volume.size = 16.0f;
  VoxelFragment f;
  f.voxel = ivec3(4, 4, 3);
  f.position = vec3(4.5f, 4.5f, 3.5f);
  f.b1 = 2.0f;
  f.b2 = 2.0f;
  const double reach = voxel_snap_reach(s, 16, f);
  ASSERT_NEAR(reach, precision(Precision::SubpixelSnap) * 7.0 / (1.0 - 16.0 * precision(Precision::SubpixelSnap)),
              1e-12);
  // Without the extrapolation (the centre's reach as if inside: one snap step) it would be 2^-8.
  EXPECT_GT(reach, 6.5 * precision(Precision::SubpixelSnap));
  const double largest = vct::test::largest_corner_move(0x1p-7);
  EXPECT_GT(largest, 1.5 * reach);
}

// ---- unorm8: RGBA8 voxel storage (rgba8-quantised) ------------------------------------------
StageSet voxel_set(const std::string& storage, const Volume& radiance) {
  StageSet s;
  s.backend = "test";
  s.storage = storage;
  s.reduction = "exact_mean";
  s.volumes["voxel.radiance"] = radiance;
  return s;
}

Volume voxel_grey(float v) {
  Volume vol(kSize, kSize, kSize, 4);
  for (size_t i = 0; i < vol.data.size(); ++i) vol.data[i] = i % 4 == 3 ? 1.0f : v;
  return vol;
}

Verdict radiance_verdict(const std::string& storage, const Volume& ref, const Volume& test) {
  const Report r = compare_stage_sets(voxel_set(storage, ref), voxel_set(storage, test));
  const StageVerdict& v = test::find(r, "voxel.radiance");
  std::printf("  voxel.radiance (%s): %s %s\n", storage.c_str(), to_string(v.verdict).c_str(), v.note.c_str());
  return v.verdict;
}

TEST(PrecisionRows, Unorm8AdmitsOneStep) {
  const VoxelModel m = voxel_model("rgba8", "exact_mean");
  ASSERT_EQ(m.abs, precision(Precision::Unorm8));
  const double bound = m.bound(0.5, 8.0), without = bound - precision(Precision::Unorm8);
  double d = 0.0;
  const Volume ref = voxel_grey(0.5f), test = shifted_rgb(ref, just_under(bound), &d);
  EXPECT_GT(d, without);
  EXPECT_EQ(radiance_verdict("rgba8", ref, test), Verdict::Pass);
}

TEST(PrecisionRows, Unorm8TwoStepsFail) {
  const Volume ref = voxel_grey(0.5f);
  EXPECT_EQ(radiance_verdict("rgba8", ref, shifted_rgb(ref, 2.0 * precision(Precision::Unorm8))), Verdict::Fail);
}

// ---- half-float: RGBA16F voxel storage (rgba16f-ulp: one binary16 ulp per side) ---------------
// At 0.5 the binary16 spacing is 2^-11 (precision(HalfFloat) relative, i.e. half an ulp rounding
// to nearest, one ulp under any rounding mode): two ulps apart, 2^-10; the float sum's 8 x 2^-23
// relative (8 fragments when the set has no counts) is the rest.
TEST(PrecisionRows, HalfFloatAdmitsOneUlpPerSide) {
  const VoxelModel m = voxel_model("rgba16f", "exact_mean");
  EXPECT_EQ(half_ulp(0.5), 2.0 * precision(Precision::HalfFloat) * 0.5);
  const double bound = m.bound(0.5, 8.0), without = bound - m.half_ulps * half_ulp(0.5);
  EXPECT_DOUBLE_EQ(bound, 8.0 * 0x1p-23 * 0.5 + 0x1p-10);
  double d = 0.0;
  const Volume ref = voxel_grey(0.5f), test = shifted_rgb(ref, just_under(bound), &d);
  EXPECT_GT(d, without);
  EXPECT_EQ(radiance_verdict("rgba16f", ref, test), Verdict::Pass);
}

// The half-ulps are taken where the test's mean may lie: a dark reference voxel (0) whose
// fragments may move its mean by a slack of 0.17 stores a half rounded at 0.17 (spacing 2^-13),
// not at 0 (2^-24).
TEST(PrecisionRows, HalfFloatUlpsAtTheFarEndOfTheSlack) {
  const VoxelModel m = voxel_model("rgba16f", "fixed_point");
  const double slack = 0.17;
  const double bound = m.bound(0.0, 1.0, slack);
  EXPECT_DOUBLE_EQ(bound, m.abs + slack + m.half_ulps * 0x1p-13);
  EXPECT_GT(bound - (m.bound(0.0, 1.0) + slack), 1e-4);  // what half-ulp(0) would have left out
}

TEST(PrecisionRows, HalfFloatFourUlpsFail) {
  const Volume ref = voxel_grey(0.5f);
  EXPECT_EQ(radiance_verdict("rgba16f", ref, shifted_rgb(ref, 4.0 * half_ulp(0.5))), Verdict::Fail);
}

// ---- srgb-encode: an 8-bit display encoding of image.final (the step the transform adds) -----
// gamma 2.2, 8 bits: the filtered bound carried through the transform plus one step 1/255 (either
// neighbour, GL 4.5 §2.3.5.1 as the row says).
DisplayTransform gamma_22_8() {
  DisplayTransform d;
  d.gamma = 2.2;
  d.bits = 8;
  return d;
}

double filtered_bound(double r) {
  const ImageModel m = image_model(ToleranceModel::Filtered);
  return m.abs + m.rel * r + m.abs_of_mean * r;  // flat image: mean |ref| = r
}

TEST(PrecisionRows, SrgbEncodeAdmitsOneStep) {
  const DisplayTransform disp = gamma_22_8();
  EXPECT_EQ(disp.quantisation_allowance(), precision(Precision::SrgbEncode) / 255.0);
  const Image ref(kSize, kSize, 3, 0.5f);
  const double bound = disp.carry_bound(0.5, filtered_bound(0.5)), without = bound - disp.quantisation_allowance();
  const Image shown(kSize, kSize, 3, float(disp.apply(0.5)));
  double d = 0.0;
  const Image test = shifted(shown, just_under(bound), &d);
  EXPECT_GT(d, without);
  EXPECT_EQ(image_verdict("image.final", ref, test, &disp), Verdict::Pass);
}

TEST(PrecisionRows, SrgbEncodeOneFurtherStepFails) {
  const DisplayTransform disp = gamma_22_8();
  const Image ref(kSize, kSize, 3, 0.5f);
  const double bound = disp.carry_bound(0.5, filtered_bound(0.5));
  const Image test = shifted(Image(kSize, kSize, 3, float(disp.apply(0.5))), bound + 1.0 / 255.0);
  EXPECT_EQ(image_verdict("image.final", ref, test, &disp), Verdict::Fail);
}

// ---- filter-weights: texture-8bit-weights (gbuffer.albedo) ----------------------------------
// The model is the row throughout: 2^-7 = 2 x 2^-8 absolute and relative (docs/compare.md).
TEST(PrecisionRows, FilterWeightsAdmitTheTextureBound) {
  const ImageModel m = image_model(ToleranceModel::Texture);
  ASSERT_EQ(m.abs, 2.0 * precision(Precision::FilterWeights));
  ASSERT_EQ(m.rel, 2.0 * precision(Precision::FilterWeights));
  expect_image_row("gbuffer.albedo", Image(kSize, kSize, 3, 0.5f), m.abs + m.rel * 0.5, 0.0);
}

TEST(PrecisionRows, FilterWeightsBeyondFails) {
  const ImageModel m = image_model(ToleranceModel::Texture);
  expect_image_beyond_fails("gbuffer.albedo", Image(kSize, kSize, 3, 0.5f), m.abs + m.rel * 0.5);
}

// ---- lod-derivatives: the admissible lambda range (gbuffer texture slack, voxel LOD) --------
// Derivatives (2, 2) texels per pixel on both axes: rho is sqrt(8) exactly (lambda 1.5); §8.14.1
// allows any f with max(|du|, |dv|) = 2 <= f <= |du| + |dv| = 4, so lambda in [1, 2], widened by
// the LOD precision kLodPrecision.
LodRange lod_range_of_2_2() {
  RhoBounds b;
  b.add_x({2.0, 2.0});
  b.add_y({2.0, 2.0});
  return b.range();
}

TEST(PrecisionRows, LodDerivativesAdmitTheSumApproximation) {
  const LodRange r = lod_range_of_2_2();
  EXPECT_DOUBLE_EQ(r.lo, 1.0 - kLodPrecision);
  EXPECT_DOUBLE_EQ(r.hi, 2.0 + kLodPrecision);
  // GL's lambda from f = |du| + |dv| (and its LOD precision) is a candidate lookup...
  double c[kMaxLodCandidates];
  const int n = lod_candidates(r, c);
  EXPECT_NE(std::find(c, c + n, r.hi), c + n);
  // ...and outside what the exact rho alone admits.
  EXPECT_GT(2.0 + kLodPrecision, std::log2(std::sqrt(8.0)));
}

TEST(PrecisionRows, LodDerivativesBeyondTheRangeIsNotACandidate) {
  const LodRange r = lod_range_of_2_2();
  const double beyond = 2.0 + 2.0 * kLodPrecision;  // one LOD quantum further
  EXPECT_GT(beyond, r.hi);
  double c[kMaxLodCandidates];
  const int n = lod_candidates(r, c);
  for (int i = 0; i < n; ++i) EXPECT_LT(c[i], beyond);
}

// ---- shading-arithmetic: shading-float (image.direct) ----------------------------------------
// Flat 0.5: 1e-5 + 2^-6 x 0.5 + 2^-10 x 0.5; without the row only the 1e-5 floor.
TEST(PrecisionRows, ShadingArithmeticAdmitsItsRelativeError) {
  const ImageModel m = image_model(ToleranceModel::Shading);
  ASSERT_EQ(m.rel, precision(Precision::ShadingArithmetic));
  expect_image_row("image.direct", Image(kSize, kSize, 3, 0.5f), m.abs + (m.rel + m.abs_of_mean) * 0.5, m.abs);
}

TEST(PrecisionRows, ShadingArithmeticBeyondFails) {
  const ImageModel m = image_model(ToleranceModel::Shading);
  expect_image_beyond_fails("image.direct", Image(kSize, kSize, 3, 0.5f), m.abs + (m.rel + m.abs_of_mean) * 0.5);
}

// ---- division-rcp-rsqrt: the light-space NDC margin (freedoms/shadow_ties.h, ndc_error) ------
// Identity matrix, p = (0.75, 0, 0): clip x 0.75, w 1, term magnitudes S_x = 0.75, S_w = 1. The
// margin is 2 g4 (S_x + |ndc| S_w) + 3 u |ndc|, the last term the two divisions (GLSL 2.5, C++ 0.5).
constexpr double kU = 0x1p-24;

TEST(PrecisionRows, DivisionTermIsInTheNdcMargin) {
  const double g4 = 4.0 * kU / (1.0 - 4.0 * kU);
  const double without = 2.0 * g4 * (0.75 + 0.75);
  const double margin = ndc_error(mat4(1.0f), vec3(0.75f, 0.0f, 0.0f), 0);
  EXPECT_DOUBLE_EQ(margin, without + 2.0 * (precision(Precision::DivisionRcpRsqrt) + 0.5) * kU * 0.75);
  EXPECT_GT(margin, without);
}

// The reverse, found by these tests: GLSL's 2.5 ulp of a result in [0.5, 1) is 2.5 x 2^-24 absolute,
// because one ulp is up to 2u |x| (u = 2^-24 is half an ulp at 1). Two evaluations that differ only in their
// divisions (2.5 ulp + 0.5 ulp at ndc 0.5) lie no further apart than the dot products' terms plus
// the division term allow: ndc_error carries 2 (2.5 + 0.5) u |ndc| (it carried 3u |ndc|, half of it,
// until session 15).
TEST(PrecisionRows, DivisionTwoPointFiveUlpAtHalfIsCovered) {
  const double g4 = 4.0 * kU / (1.0 - 4.0 * kU);
  const double dots = 2.0 * g4 * (0.5 + 0.5);
  const double ulp = 0x1p-24;  // of a float in [0.5, 1)
  const double divisions = (precision(Precision::DivisionRcpRsqrt) + 0.5) * ulp;
  EXPECT_GE(ndc_error(mat4(1.0f), vec3(0.5f, 0.0f, 0.0f), 0), dots + divisions);
}

// ---- blending: image.particles (filtered-8bit) -----------------------------------------------
// 64 additive layers each rounded to the float target (2^-24 relative per add) are admitted; the
// filtered bound has no term of its own for them (its 2^-5 relative is the cone lookups', far
// larger), so no case fails without the row: it is subsumed, not carried.
TEST(PrecisionRows, BlendingRoundingIsAdmitted) {
  const Image ref(kSize, kSize, 3, 0.5f);
  const double blending = 64.0 * precision(Precision::Blending) * 0.5;
  EXPECT_LT(blending, filtered_bound(0.5));
  EXPECT_EQ(image_verdict("image.particles", ref, shifted(ref, 0x1p-18)), Verdict::Pass);  // >= the 64 adds
}

TEST(PrecisionRows, BlendingBeyondTheFilteredBoundFails) {
  expect_image_beyond_fails("image.particles", Image(kSize, kSize, 3, 0.5f), filtered_bound(0.5));
}

// Every row names its tests, and each PrecisionRows case it names exists (a renamed case would
// leave the docs' "tested by" column pointing at nothing).
TEST(PrecisionRows, EveryRowNamesTestsThatExist) {
  const ::testing::TestSuite* suite = nullptr;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i)
    if (std::string(unit.GetTestSuite(i)->name()) == "PrecisionRows") suite = unit.GetTestSuite(i);
  ASSERT_NE(suite, nullptr);
  const auto exists = [&](const std::string& name) {
    for (int i = 0; i < suite->total_test_count(); ++i)
      if (name == suite->GetTestInfo(i)->name()) return true;
    return false;
  };
  for (const PrecisionRow& r : precision_table()) {
    const std::string tests = r.test;
    EXPECT_FALSE(tests.empty()) << r.name;
    if (r.id == Precision::MsaaResolve) {
      EXPECT_EQ(tests, "-") << "msaa-resolve is carried nowhere";
    }
    const std::string prefix = "PrecisionRows.";
    for (size_t at = tests.find(prefix); at != std::string::npos; at = tests.find(prefix, at + 1)) {
      size_t end = at + prefix.size();
      while (end < tests.size() && (std::isalnum(static_cast<unsigned char>(tests[end])) || tests[end] == '_')) ++end;
      const std::string name = tests.substr(at + prefix.size(), end - at - prefix.size());
      EXPECT_TRUE(exists(name)) << r.name << " names PrecisionRows." << name;
    }
  }
}

}  // namespace
}  // namespace vct::cmp
