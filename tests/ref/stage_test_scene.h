// Small scenes built in code for the stage tests and the stage benchmark (no loader needed).
#pragma once

#include <vector>

#include "scene/scene.h"
#include "test_box_scene.h"

namespace vct::test {

inline uint32_t add_material(Scene& s, vec3 albedo, vec3 emission = vec3(0.0f), float metallic = 0.0f,
                             float roughness = 1.0f) {
  Material m;
  m.base_color_factor = vec4(albedo, 1.0f);
  m.metallic_factor = metallic;
  m.roughness_factor = roughness;
  m.emissive_factor = emission;
  m.double_sided = true;
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}

inline void add_triangle(Scene& s, vec3 a, vec3 b, vec3 c, uint32_t material) {
  const vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const uint32_t base = uint32_t(s.positions.size());
  for (const vec3& p : {a, b, c}) {
    s.positions.push_back(p);
    s.normals.push_back(n);
    s.uv0.push_back(vec2(0.0f));
    s.bounds.add(p);
  }
  s.triangles.push_back(uvec3(base, base + 1, base + 2));
  s.triangle_material.push_back(material);
}

/// Axis-aligned box [lo, hi] as 12 triangles with outward normals.
inline void add_box(Scene& s, vec3 lo, vec3 hi, uint32_t m) {
  add_quad(s, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}, {0, -1, 0}, m);
  add_quad(s, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, {0, 1, 0}, m);
  add_quad(s, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}, {-1, 0, 0}, m);
  add_quad(s, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}, {1, 0, 0}, m);
  add_quad(s, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, {0, 0, -1}, m);
  add_quad(s, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, {0, 0, 1}, m);
}

// A camera 3 m above the origin looking straight down (+y up in the scene, -z up in the image):
// the analytic plane-under-a-light tests' view.
inline void top_camera(Scene& s) {
  s.camera.position = vec3(0.0f, 3.0f, 0.001f);
  s.camera.forward = vec3(0.0f, -1.0f, 0.0f);
  s.camera.up = vec3(0.0f, 0.0f, -1.0f);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
}

// A camera at `position` looking along -z (+y up), far plane 10 m: the front views of the
// lamp-near-a-wall and alpha-card scenes.
inline void front_camera(Scene& s, const vec3& position, float yfov, float znear) {
  s.camera.position = position;
  s.camera.forward = vec3(0.0f, 0.0f, -1.0f);
  s.camera.up = vec3(0.0f, 1.0f, 0.0f);
  s.camera.yfov = yfov;
  s.camera.znear = znear;
  s.camera.zfar = 10.0f;
}

/// A small Cornell-like room: floor, back and side walls, a box, an emissive panel, one spot light
/// pointing down, camera in front. Everything the stages touch, in ~40 triangles.
inline Scene stage_room() {
  Scene s;
  s.source = "test:stage_room";
  const uint32_t white = add_material(s, vec3(0.8f));
  const uint32_t red = add_material(s, vec3(0.8f, 0.1f, 0.1f));
  const uint32_t green = add_material(s, vec3(0.1f, 0.8f, 0.1f), vec3(0.0f), 0.0f, 0.4f);
  const uint32_t lamp = add_material(s, vec3(0.5f), vec3(4.0f, 3.0f, 2.0f));
  add_quad(s, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1, 0}, white);     // floor
  add_quad(s, {-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, {0, 0, 1}, white);   // back
  add_quad(s, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, {-1, 0, 1}, {1, 0, 0}, red);     // left
  add_quad(s, {1, 0, -1}, {1, 2, -1}, {1, 2, 1}, {1, 0, 1}, {-1, 0, 0}, green);      // right
  add_quad(s, {-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, {0, -1, 0}, white);    // ceiling
  add_box(s, {-0.3f, 0.0f, -0.4f}, {0.3f, 0.7f, 0.1f}, white);
  add_quad(s, {0.5f, 0.4f, -0.99f}, {0.8f, 0.4f, -0.99f}, {0.8f, 0.9f, -0.99f}, {0.5f, 0.9f, -0.99f}, {0, 0, 1}, lamp);
  Light l;
  l.position = vec3(0.1f, 1.9f, 0.2f);
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  l.intensity = 8.0f;
  l.inner_cone_angle = 0.5f;
  l.outer_cone_angle = 0.8f;
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  s.camera.position = vec3(0.0f, 1.0f, 3.2f);
  s.camera.forward = vec3(0.0f, 0.0f, -1.0f);
  s.camera.yfov = 0.8f;
  s.camera.znear = 0.1f;
  s.camera.zfar = 10.0f;
  return s;
}

}  // namespace vct::test
