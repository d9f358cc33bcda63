// Generated tangent frames (scene/tangents.h): orthonormal to the normal, along +u, with the
// glTF handedness (bitangent toward decreasing v), and stable where UVs give no direction.
#include <gtest/gtest.h>

#include "scene/tangents.h"

namespace vct {
namespace {

TEST(Tangents, AnyPerpendicularIsUnitAndOrthogonal) {
  for (const vec3& n : {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), glm::normalize(vec3(1, 1, 1)),
                        glm::normalize(vec3(-0.2f, 0.9f, 0.1f))}) {
    const vec3 t = any_perpendicular(n);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-6f);
  }
}

TEST(Tangents, PlanarQuadWithRotatedUvs) {
  // Quad in the xz plane (normal +y), UVs rotated 90 degrees: u grows along -z, v along -x.
  const std::vector<vec3> p = {{0, 0, 0}, {0, 0, -1}, {-1, 0, -1}, {-1, 0, 0}};
  const std::vector<vec3> n(4, vec3(0, 1, 0));
  const std::vector<vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<uvec3> tris = {{0, 1, 2}, {0, 2, 3}};
  const auto t = generate_tangents(p, n, uv, tris);
  for (const vec4& x : t) {
    EXPECT_NEAR(glm::length(vec3(x) - vec3(0, 0, -1)), 0.0f, 1e-6f);
    // B = cross(N, T) * w must point toward decreasing v, i.e. +x.
    EXPECT_NEAR(glm::length(glm::cross(vec3(0, 1, 0), vec3(x)) * x.w - vec3(1, 0, 0)), 0.0f, 1e-6f);
  }
}

TEST(Tangents, CurvedNormalsGetGramSchmidtTangents) {
  // Same flat geometry, tilted vertex normals: tangents stay unit and orthogonal to each normal.
  const std::vector<vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<vec3> n = {glm::normalize(vec3(0.3f, 0, 1)), glm::normalize(vec3(-0.3f, 0, 1)),
                               glm::normalize(vec3(-0.3f, 0.2f, 1)), glm::normalize(vec3(0.3f, 0.2f, 1))};
  const std::vector<vec2> uv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  const auto t = generate_tangents(p, n, uv, {{0, 1, 2}, {0, 2, 3}});
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::length(vec3(t[i])), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(vec3(t[i]), n[i]), 0.0f, 1e-6f);
    EXPECT_GT(t[i].x, 0.9f);  // still mostly +u = +x
    EXPECT_EQ(t[i].w, 1.0f);
  }
}

TEST(Tangents, NoUvsOrCollapsedUvsFallBackToAPerpendicular) {
  const std::vector<vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<vec3> n(3, vec3(0, 0, 1));
  for (const auto& uv : {std::vector<vec2>{}, std::vector<vec2>(3, vec2(0.5f))}) {
    const auto t = generate_tangents(p, n, uv, {{0, 1, 2}});
    for (const vec4& x : t) {
      EXPECT_NEAR(glm::length(vec3(x)), 1.0f, 1e-6f);
      EXPECT_NEAR(x.z, 0.0f, 1e-6f);
      EXPECT_EQ(x.w, 1.0f);
    }
  }
}

TEST(Tangents, OrthogonalizeKeepsHandedness) {
  const vec4 t = orthogonalize_tangent(vec3(0, 0, 1), vec4(1, 0, 0.5f, -1));
  EXPECT_NEAR(glm::length(vec3(t) - vec3(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(t.w, -1.0f);
}

}  // namespace
}  // namespace vct
