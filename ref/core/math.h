// Math vocabulary shared by every module: GLM types under short names.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstdint>
#include <limits>

namespace vct {
using glm::ivec2;
using glm::ivec3;
using glm::mat3;
using glm::mat4;
using glm::quat;
using glm::uvec3;
using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;

/// Axis-aligned box; empty() until something is added.
struct Bounds3 {
  vec3 lo{std::numeric_limits<float>::max()};
  vec3 hi{-std::numeric_limits<float>::max()};
  void add(const vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
  vec3 extent() const { return hi - lo; }
  vec3 center() const { return (lo + hi) * 0.5f; }
};
}  // namespace vct
