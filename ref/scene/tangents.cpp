#include "scene/tangents.h"

#include <cmath>

namespace vct {

vec3 any_perpendicular(const vec3& n) {
  // Cross with the axis least aligned with n, so the result is never near zero.
  const vec3 a = std::abs(n.x) < 0.57f ? vec3(1, 0, 0) : (std::abs(n.y) < 0.57f ? vec3(0, 1, 0) : vec3(0, 0, 1));
  return glm::normalize(glm::cross(a, n));
}

vec4 orthogonalize_tangent(const vec3& n, const vec4& t) {
  const vec3 v = vec3(t) - n * glm::dot(n, vec3(t));
  const float len = glm::length(v);
  if (!(len > 1e-6f)) return vec4(any_perpendicular(n), t.w < 0.0f ? -1.0f : 1.0f);
  return vec4(v / len, t.w < 0.0f ? -1.0f : 1.0f);
}

std::vector<vec4> generate_tangents(const std::vector<vec3>& positions, const std::vector<vec3>& normals,
                                    const std::vector<vec2>& uv, const std::vector<uvec3>& triangles) {
  const size_t n = positions.size();
  std::vector<glm::dvec3> tan(n, glm::dvec3(0.0)), bit(n, glm::dvec3(0.0));
  if (!uv.empty()) {
    for (const uvec3& t : triangles) {
      const glm::dvec3 p0(positions[t.x]), p1(positions[t.y]), p2(positions[t.z]);
      const glm::dvec2 w0(uv[t.x]), w1(uv[t.y]), w2(uv[t.z]);
      const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
      const glm::dvec2 d1 = w1 - w0, d2 = w2 - w0;
      const double det = d1.x * d2.y - d2.x * d1.y;
      if (std::abs(det) < 1e-20) continue;  // UVs collapse: no direction to learn
      // dP/du and dP/dv of the triangle's affine parameterization; the magnitudes weight
      // triangles by how much surface one unit of UV covers (no angle weighting, unlike Mikk).
      const glm::dvec3 sdir = (e1 * d2.y - e2 * d1.y) / det;
      const glm::dvec3 tdir = (e2 * d1.x - e1 * d2.x) / det;
      for (uint32_t v : {t.x, t.y, t.z}) {
        tan[v] += sdir;
        bit[v] += tdir;
      }
    }
  }
  std::vector<vec4> out(n);
  for (size_t i = 0; i < n; ++i) {
    const vec3 nrm = normals[i];
    const vec3 t = vec3(tan[i]);
    // glTF UVs put v = 0 at the top of the image while normal maps are "+Y up" (OpenGL
    // convention, as the glTF Sample Viewer and Blender use): the bitangent cross(N, T) * w
    // must point toward *decreasing* v, i.e. against dP/dv.
    const float w = glm::dot(glm::cross(nrm, t), vec3(bit[i])) > 0.0f ? -1.0f : 1.0f;
    out[i] = orthogonalize_tangent(nrm, vec4(t, w));
  }
  return out;
}

}  // namespace vct
