// The precision table (issue 34 item 1): every conversion and fixed-function operation a correct
// GL may perform differently from the reference, with the error it is allowed, where that comes
// from (a GL 4.5 / GLSL 4.50 section or a conformance threshold) and every stage that consumes it.
// dEQP's way: a precision is derived once, per format or unit, and carried into every stage that
// reads the value. The bounds read their constants from here (compare/tolerance.cpp, the voxel
// shading slack's sRGB term); docs/compare.md's "Precision table" is precision_table_markdown()
// (`vct stages --rules`), checked by tests/cli/docs_tables_test.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace vct {

enum class Precision : uint8_t {
  SubpixelSnap,
  DepthInterpolation,
  DepthPlaneSetup,
  DepthPlaneSnap,
  DepthUnorm,
  AttributeInterpolation,
  AttributeExtrapolation,
  Unorm8,
  Unorm16,
  HalfFloat,
  SrgbDecode,
  SrgbEncode,
  FilterWeights,
  LodDerivatives,
  ShadingArithmetic,
  DivisionRcpRsqrt,
  Blending,
  MsaaResolve,
  kCount
};
inline constexpr size_t kPrecisionCount = size_t(Precision::kCount);

struct PrecisionRow {
  Precision id;
  const char* name;        // short name, as tests and docs cite it
  const char* conversion;  // what is converted or computed
  double value;            // the allowed error in `unit` (0 where it is not one number)
  const char* allowed;     // the allowed error in words
  const char* source;      // the spec section or conformance threshold it comes from
  const char* consumers;   // the stages whose bound or freedom carries it, and where
  // The tests that fail without the row (an error the row allows is admitted only through its
  // term) and that a GL off by more FAILs (Suite.Case, tests/compare/precision_rows_test.cpp
  // unless named; "-" where the row is carried nowhere).
  const char* test;
};

/// The table, in Precision order.
const std::array<PrecisionRow, kPrecisionCount>& precision_table();
const PrecisionRow& precision_row(Precision p);
/// The row's allowed error (its `value`).
double precision(Precision p);

/// docs/compare.md's "Precision table" (Markdown), written from precision_table().
std::string precision_table_markdown();

}  // namespace vct
