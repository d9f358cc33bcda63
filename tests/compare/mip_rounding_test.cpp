// The GL mip step judged on the test's own level below (compare/mip_rounding.h, docs/compare.md
// "Mip rounding"): hand-computed children whose mean lies above, on and below a rounding
// midpoint, and the wiring into compare (our GL backend only).
#include <gtest/gtest.h>

#include <cmath>

#include "compare/mip_rounding.h"
#include "compare/stage_compare.h"
#include "stages/reduction.h"
#include "stages/stage_types.h"
#include "find_verdict.h"

namespace vct::cmp {
namespace {

// Half steps in [0.125, 0.25) are 2^-13: "units" below count them.
const float kUnit = std::ldexp(1.0f, -13);

// A 2³ level whose red channels are `kids` (others 0, opacity 1) and its 1³ parent storing `red`.
struct Pair {
  Volume child{2, 2, 2, 4}, parent{1, 1, 1, 4};
};
Pair pair(const float (&kids)[8], float red) {
  Pair p;
  for (int k = 0; k < 8; ++k) {
    float* v = p.child.voxel(k & 1, k >> 1 & 1, k >> 2);
    v[0] = kids[k];
    v[3] = 1.0f;
  }
  p.parent.voxel(0, 0, 0)[0] = red;
  p.parent.voxel(0, 0, 0)[3] = 1.0f;
  return p;
}

// 1 + 3 * 2^-12 over eight children: mean 2^-3 + 3 * 2^-15 = 1024.75 units.
const float kAbove[8] = {1.0f, std::ldexp(1.0f, -12), std::ldexp(1.0f, -12), std::ldexp(1.0f, -12), 0, 0, 0, 0};
// 1 + 2 * 2^-12: mean 1024.5 units, exactly a midpoint.
const float kMidpoint[8] = {1.0f, std::ldexp(1.0f, -12), std::ldexp(1.0f, -12), 0, 0, 0, 0, 0};

TEST(MipRounding, NearestEvenAboveTheMidpointIsTheOnlyAdmissibleHalf) {
  const Pair good = pair(kAbove, 1025 * kUnit);
  const MipRoundingCheck r = check_iso_mip_rounding(good.child, good.parent, "rgba16f");
  EXPECT_EQ(r.checked, 4u);  // four channels
  EXPECT_EQ(r.violations, 0u);
  const Pair truncated = pair(kAbove, 1024 * kUnit);
  EXPECT_EQ(check_iso_mip_rounding(truncated.child, truncated.parent, "rgba16f").violations, 1u);
  const Pair too_far = pair(kAbove, 1026 * kUnit);
  EXPECT_EQ(check_iso_mip_rounding(too_far.child, too_far.parent, "rgba16f").violations, 1u);
}

TEST(MipRounding, AMeanOnAMidpointAdmitsBothNeighbours) {
  // The float sum's rounding may land either side of 1024.5 units, and each side rounds its own
  // way: both neighbours are admissible, nothing further.
  for (int units : {1024, 1025}) {
    const Pair p = pair(kMidpoint, float(units) * kUnit);
    EXPECT_EQ(check_iso_mip_rounding(p.child, p.parent, "rgba16f").violations, 0u) << units;
  }
  const Pair p = pair(kMidpoint, 1023 * kUnit);
  EXPECT_EQ(check_iso_mip_rounding(p.child, p.parent, "rgba16f").violations, 1u);
}

TEST(MipRounding, Unorm8StoresRoundToTheNearestStep) {
  // Children summing to 8 * 100.7 / 255: the mean is 100.7 steps, admissible 101 only.
  const float c = 100.7f / 255.0f;
  const float kids[8] = {c, c, c, c, c, c, c, c};
  const Pair good = pair(kids, 101.0f / 255.0f);
  EXPECT_EQ(check_iso_mip_rounding(good.child, good.parent, "rgba8").violations, 0u);
  const Pair truncated = pair(kids, 100.0f / 255.0f);
  EXPECT_EQ(check_iso_mip_rounding(truncated.child, truncated.parent, "rgba8").violations, 1u);
}

TEST(MipRounding, UnroundedStorageOrMismatchedSizesAreNotChecked) {
  const Pair p = pair(kAbove, 1024 * kUnit);
  EXPECT_EQ(check_iso_mip_rounding(p.child, p.parent, "rgba32f").checked, 0u);
  EXPECT_EQ(check_iso_mip_rounding(p.parent, p.parent, "rgba16f").checked, 0u);
}

StageSet two_levels(const std::string& backend, float red) {
  const Pair p = pair(kAbove, red);
  StageSet s;
  s.backend = backend;
  s.facts.renderer = "a driver";  // rendered, not simulated: the step check applies to backend gl
  s.storage = "rgba16f";
  s.reduction = "fixed_point";
  s.volumes["voxel.radiance"] = p.child;
  s.volumes["mip.iso.1"] = p.parent;
  return s;
}

TEST(MipRounding, CompareFailsOurGlMipThatTruncatesAndOnlyOurs) {
  // 1024 units is 1.2e-4 below the reference's 1025: well inside the end-to-end mip bound, so
  // only the step check can fail it.
  const StageSet ref = two_levels("ref", 1025 * kUnit);
  const Report truncated = compare_stage_sets(ref, two_levels("gl", 1024 * kUnit));
  const StageVerdict& bad = test::find(truncated, "mip.iso.1");
  EXPECT_EQ(bad.verdict, Verdict::Fail) << bad.note;
  EXPECT_EQ(bad.extra.value("step_rounding_violations", 0), 1);
  const Report rounded = compare_stage_sets(ref, two_levels("gl", 1025 * kUnit));
  const StageVerdict& good = test::find(rounded, "mip.iso.1");
  EXPECT_NE(good.verdict, Verdict::Fail) << good.note;
  EXPECT_EQ(good.extra.value("step_rounding_checked", 0), 4);
  // Another engine's store conversion rounds as its implementation does (GL leaves it open).
  const Report foreign = compare_stage_sets(ref, two_levels("my-engine", 1024 * kUnit));
  const StageVerdict& other = test::find(foreign, "mip.iso.1");
  EXPECT_NE(other.verdict, Verdict::Fail) << other.note;
  EXPECT_EQ(other.extra.count("step_rounding_violations"), 0u);
}

// The anisotropic step (mip_aniso.comp): along x, the front child over the back one, the four
// pairs averaged. Children: in x = 0 red 0 and opacity 0.5 everywhere, but the pair at (y, z) =
// (0, 0) has red 0.5; in x = 1 opacity 0.5, and red 3 * 2^-12 at (y, z) = (1, 0). Marching +x
// (front x = 0): red = 0.25 (0.5 + 0.5 * 3 * 2^-12) = 2^-3 + 3 * 2^-15 = 1024.75 units, so 1025
// only; opacity 0.5 + 0.5 * 0.5 = 0.75 in every pair, exact. Marching -x (front x = 1): red =
// 0.25 (3 * 2^-12 + 0.5 * 0.5) = 0.0625 + 3 * 2^-14 (units of 2^-14 there): another value.
Pair aniso_pair(float red) {
  Pair p;
  for (int k = 0; k < 8; ++k) p.child.voxel(k & 1, k >> 1 & 1, k >> 2)[3] = 0.5f;
  p.child.voxel(0, 0, 0)[0] = 0.5f;
  p.child.voxel(1, 1, 0)[0] = 3.0f * std::ldexp(1.0f, -12);
  p.parent.voxel(0, 0, 0)[0] = red;
  p.parent.voxel(0, 0, 0)[3] = 0.75f;
  return p;
}

TEST(MipRounding, AnisoFrontToBackCompositeRoundsToTheOnlyAdmissibleHalf) {
  const Pair good = aniso_pair(1025 * kUnit);
  const MipRoundingCheck r = check_aniso_mip_rounding(good.child, good.parent, "rgba16f", kPosX);
  EXPECT_EQ(r.checked, 4u);
  EXPECT_EQ(r.violations, 0u);
  const Pair truncated = aniso_pair(1024 * kUnit);
  EXPECT_EQ(check_aniso_mip_rounding(truncated.child, truncated.parent, "rgba16f", kPosX).violations, 1u);
  // The same children marched the other way composite the other child in front: 1025 units is not it.
  EXPECT_EQ(check_aniso_mip_rounding(good.child, good.parent, "rgba16f", kNegX).violations, 1u);
  Pair back = aniso_pair(0.0625f + 3.0f * std::ldexp(1.0f, -14));
  EXPECT_EQ(check_aniso_mip_rounding(back.child, back.parent, "rgba16f", kNegX).violations, 0u);
}

TEST(MipRounding, AnisoOpacityIsClampedToOneAndNothingAbove) {
  // Opacity 0.9 in front of 0.9: 0.99 composited; 1.8 if added (GL fault alpha_unclamped).
  Pair p;  // colour 0 everywhere
  for (int k = 0; k < 8; ++k) p.child.voxel(k & 1, k >> 1 & 1, k >> 2)[3] = 0.9f;
  p.parent.voxel(0, 0, 0)[3] = quantize_half(0.99f);
  EXPECT_EQ(check_aniso_mip_rounding(p.child, p.parent, "rgba16f", kPosY).violations, 0u);
  p.parent.voxel(0, 0, 0)[3] = 1.0f;
  EXPECT_EQ(check_aniso_mip_rounding(p.child, p.parent, "rgba16f", kPosY).violations, 1u);
}

}  // namespace
}  // namespace vct::cmp
