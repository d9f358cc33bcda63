// A CPU-vs-GPU element harness for the shared header (ref/shared/vct_shared.h and
// voxel_fixed_point.h), after Falcor's element tests: each case evaluates one shared function on a
// grid of inputs in a GLSL compute shader (inputs and outputs travel as raw 32-bit words in SSBOs),
// the same function runs in C++, and the two are compared element by element against a bound the
// case derives per point from the GLSL 4.50 precision rules (docs/compare.md, "Shared-header
// element tests"). A difference is reported with the function's name and the worst input.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/math.h"

namespace vct::gl::test {

/// One output word group (a uvec4 slot) as the C++ side expects it. bound == 0 in a component
/// demands identical bits; otherwise |gl - cpu| <= bound (+ FLT_MIN for flushed denormals).
struct ExpectedSlot {
  glm::uvec4 bits{0u};
  glm::vec4 bound{0.0f};
};

/// One shared function on a grid. `glsl` is the body of a GLSL function that reads its inputs
/// with fin(k) / uin(k) (slot k of this point, as vec4 / uvec4) and writes with put(k, vec4) /
/// putu(k, uvec4). `cpu` computes the expected slots from the same input words.
struct ElementCase {
  std::string function;
  std::string in_kinds;  // one char per input slot: 'f' (floats) or 'u' (uints), for messages
  int outputs = 1;
  std::string glsl;
  std::function<std::vector<ExpectedSlot>(const glm::uvec4* in)> cpu;
  std::vector<glm::uvec4> inputs;  // points * in_kinds.size() slots
  size_t points() const { return in_kinds.empty() ? 0 : inputs.size() / in_kinds.size(); }
};

/// The outcome of one case: the worst element (largest error / bound, a bit mismatch of an
/// exact component counting as infinite) and the largest error in ulps of the C++ value.
struct ElementResult {
  std::string function;
  size_t points = 0;
  bool pass = true;
  double worst_ratio = 0.0;  // max |gl - cpu| / bound over non-exact components (0 if all equal)
  double worst_ulps = 0.0;   // max distance in representable floats between gl and cpu
  double worst_abs = 0.0;    // max |gl - cpu|
  std::string message;       // names the function and the worst input (on failure: why)
};

inline glm::uvec4 words(const glm::vec4& v) {
  glm::uvec4 r;
  std::memcpy(&r, &v, sizeof r);
  return r;
}
inline glm::vec4 floats(const glm::uvec4& w) {
  glm::vec4 r;
  std::memcpy(&r, &w, sizeof r);
  return r;
}
inline float as_float(uint32_t w) {
  float f;
  std::memcpy(&f, &w, sizeof f);
  return f;
}

/// The shared headers as GLSL sees them (gl/gl_program.cpp's prelude), with every occurrence of
/// each `from` replaced by `to` when a perturbation is given (the harness's own failure check).
std::string shared_header_glsl(
    const std::vector<std::pair<std::string, std::string>>& perturb = {});

/// Runs every case on the current GL context with one compute program built from `header`
/// (shared_header_glsl()) and compares with the C++ side. Throws std::runtime_error on GL
/// failures (compile errors name the case's source).
std::vector<ElementResult> run_element_cases(const std::vector<ElementCase>& cases,
                                             const std::string& header);

}  // namespace vct::gl::test
