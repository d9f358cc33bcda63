// The march-end tie (docs/compare.md, "The march-end tie"): where a cone's last in-volume sample
// lies within the step positions' precision of a face it leaves through, a correct GL may take one
// sample less (march_end -1) or one more sampled at the face (+1); where its steps never came from
// tan(aperture / 2) both sides' positions are the same floats and there is no alternative.
#include <gtest/gtest.h>

#include <cmath>

#include "stages/cone_trace.h"
#include "stages/mips.h"

namespace vct {
namespace {

// An 8^3 volume of faint fog: every sample adds light.
VoxelMips fog() {
  Volume v(8, 8, 8, 4);
  for (size_t i = 0; i < v.voxel_count(); ++i) {
    v.data[i * 4 + 0] = v.data[i * 4 + 1] = v.data[i * 4 + 2] = 0.05f;
    v.data[i * 4 + 3] = 0.05f;
  }
  return build_mips(v, false);
}

MarchParams params(int march_end) {
  MarchParams p;
  p.start_offset = 0.3f;
  p.quality = 0.5f;
  p.march_end = march_end;
  return p;
}

// A wide cone along +x (60 degrees: from the first sample on, 2 t tan 30 > 1/8, so every step's
// length comes from the tangent), its origin placed so that its last sample before x = 1 (in a
// march from x = 0) lands at x = 1 + offset. The distances are the march's own arithmetic.
Cone wide_cone_with_last_sample_at(const VoxelMips& mips, float offset) {
  Cone c;
  c.direction = vec3(1.0f, 0.0f, 0.0f);
  c.aperture = 2.0f * std::atan(1.0f / std::sqrt(3.0f));
  const MarchParams p = params(0);
  const float voxel = 1.0f / float(mips.iso[0].nx), tan_half = std::tan(0.5f * c.aperture);
  float t = p.start_offset, last = t;
  while (t < 1.0f) {
    last = t;
    t += std::max(std::max(voxel, 2.0f * t * tan_half) * p.quality, 1e-6f);
  }
  c.origin = vec3(1.0f + offset - last, 0.5f, 0.5f);
  return c;
}

TEST(MarchEnd, ALastSampleOnTheExitFaceMayBeDroppedOrKept) {
  const VoxelMips mips = fog();
  // Just inside the face: the plain march takes it, a GL a hair further does not.
  const Cone inside = wide_cone_with_last_sample_at(mips, -4e-7f);
  std::vector<ConeSample> plain, shorter, longer;
  const vec4 a = trace_cone(mips, inside, params(0), &plain);
  const vec4 s = trace_cone(mips, inside, params(-1), &shorter);
  const vec4 l = trace_cone(mips, inside, params(+1), &longer);
  ASSERT_GE(plain.size(), 2u);
  EXPECT_EQ(shorter.size(), plain.size() - 1);
  EXPECT_LT(s.a, a.a);
  EXPECT_EQ(longer.size(), plain.size());
  EXPECT_EQ(l, a);
  // Just outside: the plain march stops, a GL a hair nearer samples it (at the face).
  const Cone outside = wide_cone_with_last_sample_at(mips, 4e-7f);
  plain.clear(), shorter.clear(), longer.clear();
  const vec4 a2 = trace_cone(mips, outside, params(0), &plain);
  const vec4 l2 = trace_cone(mips, outside, params(+1), &longer);
  EXPECT_EQ(longer.size(), plain.size() + 1);
  EXPECT_EQ(longer.back().position.x, 1.0f);  // sampled at the face
  EXPECT_GT(l2.a, a2.a);
  EXPECT_EQ(trace_cone(mips, outside, params(-1)), a2);
  // Half a step from the face: no alternative either way.
  const Cone middle = wide_cone_with_last_sample_at(mips, -0.05f);
  const vec4 m = trace_cone(mips, middle, params(0));
  EXPECT_EQ(trace_cone(mips, middle, params(-1)), m);
  EXPECT_EQ(trace_cone(mips, middle, params(+1)), m);
}

// A narrow cone (1 degree) marches in voxel-sized steps (quality x 1/N, no tan): both sides add
// the same floats, so a sample exactly on the face has no alternative.
TEST(MarchEnd, StepsThatNeverUsedTheApertureHaveNoAlternative) {
  const VoxelMips mips = fog();
  Cone c;
  c.direction = vec3(1.0f, 0.0f, 0.0f);
  c.aperture = 0.0174533f;
  MarchParams p = params(0);
  p.start_offset = 0.125f;
  // t = 0.125 + k / 16: exact in float; origin 0 puts t = 1 exactly on the face.
  c.origin = vec3(0.0f, 0.5f, 0.5f);
  const vec4 plain = trace_cone(mips, c, p);
  for (int variant : {-1, +1}) {
    MarchParams q = p;
    q.march_end = variant;
    EXPECT_EQ(trace_cone(mips, c, q), plain) << variant;
  }
  EXPECT_EQ(march_end_margin(0.9f, 0.0, 0), 0.0f);
}

// The start-face tie (docs/compare.md): a cone whose origin a correct engine may place
// origin_margin away (its position reconstructed, not read) and whose first sample lies within
// that of a face, here x = 1 with the cone running along the face (+y).
Cone along_face_at(float x, float margin) {
  Cone c;
  c.direction = vec3(0.0f, 1.0f, 0.0f);
  c.aperture = 0.5f;
  c.origin = vec3(x, 0.2f, 0.5f);
  c.origin_margin = vec3(margin, margin, margin);
  return c;
}

TEST(MarchEnd, AFirstSampleJustInsideAFaceMayStartOutside) {
  const VoxelMips mips = fog();
  const Cone c = along_face_at(1.0f - 1e-6f, 4e-6f);
  const vec4 plain = trace_cone(mips, c, params(0));
  EXPECT_GT(plain.a, 0.0f);
  EXPECT_EQ(trace_cone(mips, c, params(-1)), vec4(0.0f));  // GL's origin outside: its loop breaks at once
  EXPECT_EQ(trace_cone(mips, c, params(+1)), plain);      // inside already: nothing to move
}

TEST(MarchEnd, AFirstSampleJustOutsideAFaceMayStartOnIt) {
  const VoxelMips mips = fog();
  const Cone c = along_face_at(1.0f + 1e-6f, 4e-6f);
  EXPECT_EQ(trace_cone(mips, c, params(0)), vec4(0.0f));
  EXPECT_EQ(trace_cone(mips, c, params(-1)), vec4(0.0f));
  // +1: the whole march moved onto the face, as a GL whose origin lay there marches it.
  std::vector<ConeSample> longer;
  const vec4 l = trace_cone(mips, c, params(+1), &longer);
  ASSERT_GE(longer.size(), 2u);
  for (const ConeSample& sample : longer) EXPECT_EQ(sample.position.x, 1.0f);
  Cone on_face = c;
  on_face.origin.x = 1.0f;
  on_face.origin_margin = vec3(0.0f);
  EXPECT_EQ(l, trace_cone(mips, on_face, params(0)));
}

TEST(MarchEnd, AStartBeyondTheOriginsMarginOrFromTheSameFloatsHasNoAlternative) {
  const VoxelMips mips = fog();
  for (float x : {1.0f - 1e-4f, 1.0f + 1e-4f}) {  // 25 margins from the face
    const Cone c = along_face_at(x, 4e-6f);
    const vec4 plain = trace_cone(mips, c, params(0));
    EXPECT_EQ(trace_cone(mips, c, params(-1)), plain) << x;
    EXPECT_EQ(trace_cone(mips, c, params(+1)), plain) << x;
  }
  // No origin margin (both sides march from the same floats): a cone starting on the face stays.
  const Cone same = along_face_at(1.0f, 0.0f);
  const vec4 plain = trace_cone(mips, same, params(0));
  EXPECT_GT(plain.a, 0.0f);
  EXPECT_EQ(trace_cone(mips, same, params(-1)), plain);
  EXPECT_EQ(trace_cone(mips, same, params(+1)), plain);
}

// The drift follows the derivation: GL's tan within 2^-11 (1/sin h + 1/cos h) + 2^-11 h/(sin h cos h)
// relative, carried by step / (t + step) per step.
TEST(MarchEnd, DriftPerStepIsTheTangentsPrecisionTimesTheStepsShare) {
  const double h = 0.5 * double(0.6f);
  const double eps = (1.0 / std::sin(h) + 1.0 / std::cos(h) + h / (std::sin(h) * std::cos(h))) / 2048.0 +
                     3.0 / 16777216.0;  // + 3 u: the division sin / cos (2.5 ulp) and our own tan
  EXPECT_NEAR(march_end_step_drift(0.6f, 0.3f, 0.1f), eps * double(0.1f) / double(0.3f + 0.1f), 1e-9);
  // material_room (168,123)'s specular cone, h = 16.8 degrees, 14 tan steps to t = 0.485: the
  // design's estimate was 3.5e-3 in texture units, far above the last sample's 1.7e-5 from the face.
  EXPECT_GT(march_end_margin(0.485f, 14 * march_end_step_drift(0.586f, 0.4f, 0.085f), 14), 1.7e-5f);
}

}  // namespace
}  // namespace vct
