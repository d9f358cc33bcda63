// A closed box built in code for the cone-tracing tests (no loader needed): six inward-facing
// walls of [0,1]^3, optional emission on every wall, an optional spot light inside.
#pragma once

#include <utility>

#include "scene/scene.h"

namespace vct::test {

inline void add_quad(Scene& s, vec3 a, vec3 b, vec3 c, vec3 d, vec3 n, uint32_t material) {
  if (glm::dot(glm::cross(b - a, c - a), n) < 0.0f) std::swap(b, d);  // winding agrees with n
  const uint32_t base = uint32_t(s.positions.size());
  for (const vec3& p : {a, b, c, d}) {
    s.positions.push_back(p);
    s.normals.push_back(n);
    s.uv0.push_back(vec2(0.0f));
    s.bounds.add(p);
  }
  s.triangles.push_back(uvec3(base, base + 1, base + 2));
  s.triangles.push_back(uvec3(base, base + 2, base + 3));
  s.triangle_material.push_back(material);
  s.triangle_material.push_back(material);
}

/// Closed unit box, all walls one material (albedo, emission), normals pointing inward.
inline Scene closed_box(vec3 albedo, vec3 emission) {
  Scene s;
  s.source = "test:closed_box";
  Material m;
  m.base_color_factor = vec4(albedo, 1.0f);
  m.metallic_factor = 0.0f;
  m.roughness_factor = 1.0f;
  m.emissive_factor = emission;
  m.double_sided = true;
  s.materials.push_back(m);
  add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, 0);    // floor y=0
  add_quad(s, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}, {0, -1, 0}, 0);   // ceiling y=1
  add_quad(s, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 0, 0}, 0);    // x=0
  add_quad(s, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}, {-1, 0, 0}, 0);   // x=1
  add_quad(s, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0, 0, 1}, 0);    // z=0
  add_quad(s, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0, 0, -1}, 0);   // z=1
  s.volume = fit_volume(s.bounds);
  s.camera.position = vec3(0.5f, 0.5f, 0.95f);
  s.camera.forward = vec3(0.0f, 0.0f, -1.0f);
  s.camera.yfov = 1.2f;
  s.camera.znear = 0.01f;
  s.camera.zfar = 5.0f;
  return s;
}

}  // namespace vct::test
