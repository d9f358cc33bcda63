// The precision table (core/precision.h; docs/compare.md, "Precision table"): rows in order with a
// source and consumers, the constants the freedom producers still define themselves equal to
// their rows, and the sRGB decode's half step bracketing what llvmpipe was measured to do.
#include <cmath>
#include <gtest/gtest.h>
#include <string>

#include "core/precision.h"
#include "freedoms/direct_slack.h"
#include "freedoms/lookup_precision.h"
#include "freedoms/plane_setup.h"
#include "io/srgb.h"
#include "scene/surface.h"
#include "scene/texture_lod.h"
#include "stages/raster.h"

namespace vct {
namespace {

TEST(Precision, EveryRowHasItsSourceAndItsConsumers) {
  for (size_t i = 0; i < kPrecisionCount; ++i) {
    const PrecisionRow& r = precision_table()[i];
    EXPECT_EQ(size_t(r.id), i);
    EXPECT_FALSE(std::string(r.source).empty()) << r.name;
    EXPECT_FALSE(std::string(r.consumers).empty()) << r.name;
    EXPECT_NE(precision_table_markdown().find(std::string("`") + r.name + "`"), std::string::npos) << r.name;
  }
}

// Constants defined beside the code that uses them are the table's rows.
TEST(Precision, ProducersConstantsAreTheTablesRows) {
  EXPECT_EQ(kVertexSnapStep, precision(Precision::SubpixelSnap));
  EXPECT_EQ(kLodPrecision, precision(Precision::LodDerivatives));
  EXPECT_EQ(kFloatRoundoff, precision(Precision::DepthPlaneSetup));
  EXPECT_EQ(double(kUnorm8Step), double(float(precision(Precision::Unorm8))));
  // Linear PCF: a weight off by 2^-8 on each of two axes (docs/compare.md, the engine's PCF row).
  EXPECT_EQ(double(kLinearCompareWeightStep), 2.0 * precision(Precision::FilterWeights));
}

// Half a step of the encoding either way brackets the exact decode of every 8-bit value, and the
// llvmpipe error measured in issue 34 (at most 0.34 of a step) lies inside.
TEST(Precision, SrgbDecodeHalfStepBracketsEveryTexel) {
  const float h = float(precision(Precision::SrgbDecode));
  for (int c = 1; c < 255; ++c) {
    const float exact = srgb_to_linear(float(c) / 255.0f);
    const float lo = shift_srgb_steps(vec3(exact), -h).x, hi = shift_srgb_steps(vec3(exact), h).x;
    EXPECT_NEAR(lo, srgb_to_linear((float(c) - h) / 255.0f), 2e-6f * (1.0f + exact)) << c;
    EXPECT_NEAR(hi, srgb_to_linear((float(c) + h) / 255.0f), 2e-6f * (1.0f + exact)) << c;
    const float measured_lo = srgb_to_linear((float(c) - 0.34f) / 255.0f);
    const float measured_hi = srgb_to_linear((float(c) + 0.34f) / 255.0f);
    EXPECT_LE(lo, measured_lo) << c;
    EXPECT_GE(hi, measured_hi) << c;
  }
  // A whole step is outside: the reverse of the freedom.
  EXPECT_GT(srgb_to_linear(27.0f / 255.0f), shift_srgb_steps(vec3(srgb_to_linear(26.0f / 255.0f)), h).x);
}

}  // namespace
}  // namespace vct
