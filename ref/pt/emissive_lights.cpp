#include "pt/emissive_lights.h"

#include <algorithm>
#include <cmath>

#include "pt/bsdf_sampling.h"

namespace vct::pt {

vec3 emitted_radiance(const Scene& scene, const SurfacePoint& p, const SurfaceMaterial& m, const vec3& w) {
  if (m.emission == vec3(0.0f)) return vec3(0.0f);
  const Material& mat = scene.materials[scene.triangle_material[p.triangle]];
  if (!mat.double_sided && glm::dot(p.geometric_normal, w) <= 0.0f) return vec3(0.0f);
  return m.emission;
}

namespace {
float triangle_area(const Scene& s, uint32_t t) {
  const uvec3 i = s.triangles[t];
  return 0.5f * glm::length(glm::cross(s.positions[i.y] - s.positions[i.x], s.positions[i.z] - s.positions[i.x]));
}
}  // namespace

EmissiveTriangles::EmissiveTriangles(const Scene& scene) : pdf_area_(scene.triangles.size(), 0.0f) {
  std::vector<double> weight;
  double total = 0.0;
  for (uint32_t t = 0; t < uint32_t(scene.triangles.size()); ++t) {
    const Material& m = scene.materials[scene.triangle_material[t]];
    if (!m.is_emissive()) continue;
    const float area = triangle_area(scene, t);
    // Luminance of the factor; a textured emitter is picked by its factor (unbiased either way).
    const double w = double(area) * double(std::max(luminance(m.emission()), 1e-6f));
    if (!(area > 0.0f) || !(w > 0.0)) continue;
    triangles_.push_back(t);
    weight.push_back(w);
    total += w;
  }
  double acc = 0.0;
  for (size_t i = 0; i < triangles_.size(); ++i) {
    acc += weight[i];
    cdf_.push_back(acc / total);
    pdf_area_[triangles_[i]] = float(weight[i] / total) / triangle_area(scene, triangles_[i]);
  }
  if (!cdf_.empty()) cdf_.back() = 1.0;
  for (const uint32_t t : triangles_) {
    const uvec3 i = scene.triangles[t];
    const Material& m = scene.materials[scene.triangle_material[t]];
    Geometry g;
    g.p0 = scene.positions[i.x], g.p1 = scene.positions[i.y], g.p2 = scene.positions[i.z];
    g.normal = glm::normalize(glm::cross(g.p1 - g.p0, g.p2 - g.p0));
    g.emission = m.emission();
    g.textured = m.emissive_texture.present();
    g.double_sided = m.double_sided;
    g.alpha_tested = m.alpha_tested();
    geometry_.push_back(g);
  }
}

namespace {
/// Uniform on the triangle: b0 = 1 - sqrt(u0), b1 = u1 sqrt(u0) (Osada et al. / pbrt).
void place_on_triangle(vec2 u, EmissiveTriangles::Sample& s) {
  const float su = std::sqrt(u.x);
  s.b1 = u.y * su;
  s.b2 = su * (1.0f - u.y);
}
}  // namespace

EmissiveTriangles::Sample EmissiveTriangles::sample_reusing(double x, float u_y) const {
  Sample s;
  if (triangles_.empty()) return s;
  const size_t i = std::min(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), x) - cdf_.begin()), triangles_.size() - 1);
  s.triangle = triangles_[i];
  s.emitter = uint32_t(i);
  const double lo = i > 0 ? cdf_[i - 1] : 0.0, hi = cdf_[i];
  const float u_x = std::clamp(float((x - lo) / (hi - lo)), 0.0f, 0x1.fffffep-1f);
  place_on_triangle(vec2(u_x, u_y), s);
  s.pdf_area = pdf_area_[s.triangle];
  return s;
}

EmissiveTriangles::Sample EmissiveTriangles::sample(float u_select, vec2 u) const {
  Sample s;
  if (triangles_.empty()) return s;
  const size_t i = std::min(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(u_select)) - cdf_.begin()),
                            triangles_.size() - 1);
  s.triangle = triangles_[i];
  s.emitter = uint32_t(i);
  place_on_triangle(u, s);
  s.pdf_area = pdf_area_[s.triangle];
  return s;
}

}  // namespace vct::pt
