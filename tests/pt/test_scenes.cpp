#include "test_scenes.h"

#include <array>
#include <cmath>
#include <vector>

namespace vct::pt::test {

Material lambertian(const vec3& albedo, const vec3& emission, bool double_sided) {
  Material m;
  m.base_color_factor = vec4(albedo, 1.0f);
  m.metallic_factor = 0.0f;
  m.roughness_factor = 1.0f;
  m.specular_factor = 0.0f;
  m.emissive_factor = emission;
  m.double_sided = double_sided;
  return m;
}

Material pbr(const vec3& albedo, float metallic, float roughness) {
  Material m;
  m.base_color_factor = vec4(albedo, 1.0f);
  m.metallic_factor = metallic;
  m.roughness_factor = roughness;
  return m;
}

uint32_t add_material(Scene& s, const Material& m) {
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}

void add_triangle(Scene& s, const vec3& a, const vec3& b, const vec3& c, uint32_t material) {
  const vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const vec3 t = glm::normalize(b - a);
  const auto base = uint32_t(s.positions.size());
  for (const vec3& p : {a, b, c}) {
    s.positions.push_back(p);
    s.normals.push_back(n);
    s.tangents.push_back(vec4(t, 1.0f));
    s.uv0.push_back(vec2(0.0f));
  }
  s.triangles.push_back(uvec3(base, base + 1, base + 2));
  s.triangle_material.push_back(material);
}

void add_quad(Scene& s, const vec3& corner, const vec3& eu, const vec3& ev, uint32_t material) {
  add_triangle(s, corner, corner + eu, corner + eu + ev, material);
  add_triangle(s, corner, corner + eu + ev, corner + ev, material);
}

void add_icosphere(Scene& s, const vec3& centre, float radius, int subdiv, bool inward, uint32_t material) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (vec3& p : v) p = glm::normalize(p);
  std::vector<std::array<vec3, 3>> tris;
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (const auto& tri : f) tris.push_back({v[size_t(tri[0])], v[size_t(tri[1])], v[size_t(tri[2])]});
  for (int level = 0; level < subdiv; ++level) {
    std::vector<std::array<vec3, 3>> next;
    for (const auto& tri : tris) {
      const vec3 a = glm::normalize(tri[0] + tri[1]), b = glm::normalize(tri[1] + tri[2]),
                 c = glm::normalize(tri[2] + tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    tris.swap(next);
  }
  for (const auto& tri : tris) {  // the base faces wind outward
    const vec3 a = centre + radius * tri[0], b = centre + radius * tri[1], c = centre + radius * tri[2];
    if (inward)
      add_triangle(s, a, c, b, material);
    else
      add_triangle(s, a, b, c, material);
  }
}

void add_room(Scene& s, const vec3& lo, const vec3& hi, uint32_t material) {
  const vec3 e = hi - lo;
  const vec3 x(e.x, 0, 0), y(0, e.y, 0), z(0, 0, e.z);
  add_quad(s, lo, z, x, material);                      // floor y = lo, facing +y
  add_quad(s, vec3(lo.x, hi.y, lo.z), x, z, material);  // ceiling, facing -y
  add_quad(s, lo, x, y, material);                      // back wall z = lo, facing +z
  add_quad(s, vec3(lo.x, lo.y, hi.z), y, x, material);  // front wall z = hi, facing -z
  add_quad(s, lo, y, z, material);                      // left wall x = lo, facing +x
  add_quad(s, vec3(hi.x, lo.y, lo.z), z, y, material);  // right wall x = hi, facing -x
}

Camera look_at(const vec3& eye, const vec3& target, const vec3& up, float yfov) {
  Camera c;
  c.position = eye;
  c.forward = glm::normalize(target - eye);
  c.up = up;
  c.yfov = yfov;
  c.znear = 0.01f;
  c.zfar = 100.0f;
  c.from_file = true;
  return c;
}

void finish(Scene& s) {
  if (s.materials.empty()) s.materials.push_back(Material{});
  s.bounds = Bounds3{};
  for (const vec3& p : s.positions) s.bounds.add(p);
  s.volume = fit_volume(s.bounds);
  s.source = "test:in-code";
}

}  // namespace vct::pt::test

namespace vct::pt::test {
Scene demo_room() {
  Scene s;
  const uint32_t white = add_material(s, lambertian(vec3(0.75f)));
  const uint32_t red = add_material(s, lambertian(vec3(0.7f, 0.1f, 0.1f)));
  const uint32_t lamp = add_material(s, lambertian(vec3(0.0f), vec3(6.0f, 5.0f, 4.0f)));
  const uint32_t metal = add_material(s, pbr(vec3(0.9f, 0.7f, 0.4f), 1.0f, 0.3f));
  const uint32_t glossy = add_material(s, pbr(vec3(0.2f, 0.4f, 0.8f), 0.0f, 0.2f));
  add_room(s, vec3(-1.0f, 0.0f, -1.0f), vec3(1.0f, 2.0f, 1.0f), white);
  add_quad(s, vec3(-0.999f, 0.0f, -1.0f), vec3(0, 2, 0), vec3(0, 0, 2), red);  // left wall tint, facing +x
  add_quad(s, vec3(-0.25f, 1.999f, -0.25f), vec3(0.5f, 0, 0), vec3(0, 0, 0.5f), lamp);  // facing -y
  add_quad(s, vec3(0.2f, 0.6f, -0.6f), vec3(0, 0, 0.5f), vec3(0.5f, 0, 0), metal);  // block top, +y
  add_quad(s, vec3(0.2f, 0.0f, -0.1f), vec3(0.5f, 0, 0), vec3(0, 0.6f, 0), metal);   // block front, +z
  add_icosphere(s, vec3(-0.4f, 0.35f, 0.1f), 0.35f, 2, false, glossy);
  Light l;
  l.position = vec3(0.6f, 1.8f, 0.6f);
  l.direction = glm::normalize(vec3(-0.6f, -1.0f, -0.5f));
  l.intensity = 4.0f;
  l.inner_cone_angle = 0.3f;
  l.outer_cone_angle = 0.6f;
  s.lights.push_back(l);
  s.camera = look_at(vec3(0.0f, 1.0f, 0.95f), vec3(0.0f, 1.5f, -1.0f), vec3(0, 1, 0), 1.2f);
  finish(s);
  return s;
}
}  // namespace vct::pt::test
