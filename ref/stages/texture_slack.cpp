#include "stages/texture_slack.h"

#include <algorithm>
#include <cmath>

namespace vct {

WindowBarycentrics::WindowBarycentrics(const mat4& view_proj, int width, int height)
    : inv_view_proj_(glm::inverse(glm::dmat4(view_proj))), width_(width), height_(height) {}

bool WindowBarycentrics::at(const Scene& scene, uint32_t triangle, double wx, double wy, glm::dvec2& b) const {
  // Double precision: the shifts are 2^-8 pixel, a barycentric change of ~1e-6 on large images.
  const double nx = 2.0 * wx / double(width_) - 1.0, ny = 2.0 * wy / double(height_) - 1.0;
  const glm::dvec4 n = inv_view_proj_ * glm::dvec4(nx, ny, -1.0, 1.0);
  const glm::dvec4 f = inv_view_proj_ * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 o = glm::dvec3(n) / n.w, d = glm::dvec3(f) / f.w - o;
  const uvec3 t = scene.triangles[triangle];
  const glm::dvec3 p0(scene.positions[t.x]), e1 = glm::dvec3(scene.positions[t.y]) - p0,
      e2 = glm::dvec3(scene.positions[t.z]) - p0;
  // Moller-Trumbore without the inside test: the plane's barycentrics, extrapolated.
  const glm::dvec3 pv = glm::cross(d, e2);
  const double det = glm::dot(e1, pv);
  if (std::abs(det) < 1e-300) return false;
  const glm::dvec3 tv = o - p0, qv = glm::cross(tv, e1);
  b = glm::dvec2(glm::dot(tv, pv), glm::dot(d, qv)) / det;
  return std::isfinite(b.x) && std::isfinite(b.y);
}

namespace {

bool textured(const Material& m) {
  return m.base_color_texture.present() || m.metallic_roughness_texture.present() || m.normal_texture.present() ||
         m.emissive_texture.present();
}

float max_abs_diff(const vec3& a, const vec3& b) {
  const vec3 d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

vec4 difference(const SurfaceMaterial& a, const SurfaceMaterial& b) {
  const vec3 ma(a.metallic, a.roughness, a.specular_factor), mb(b.metallic, b.roughness, b.specular_factor);
  return vec4(max_abs_diff(a.shading_normal, b.shading_normal), max_abs_diff(a.albedo, b.albedo), max_abs_diff(ma, mb),
              max_abs_diff(a.emission, b.emission));
}

}  // namespace

int lod_candidates(const LodRange& range, double out[kMaxLodCandidates]) {
  int n = 0;
  out[n++] = range.lo;
  if (range.lo <= 0.0 && range.hi > 0.0) out[n++] = 1e-9;  // minified at level 0
  for (double k = std::floor(range.lo) + 1.0; k < range.hi && n < kMaxLodCandidates - 1; k += 1.0) {
    if (k > 0.0) out[n++] = k;
  }
  if (range.hi > out[n - 1]) out[n++] = range.hi;
  return n;
}

bool is_textured(const Material& m) {
  return textured(m);
}

int shifted_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                           uint32_t triangle, const vec3& bary, SurfacePoint out[kSlackShifts]) {
  // The shift set is symmetric, so the row direction (image rows grow downward, window y upward)
  // only matters for the centre itself.
  const double cx = double(x) + 0.5, cy = double(wb.height()) - double(row) - 0.5;
  glm::dvec2 bc;
  if (!wb.at(scene, triangle, cx, cy, bc)) return 0;
  constexpr double s = kVertexSnapStep;
  // The centre and the corners: the change of a (locally) linear value peaks there, as in the
  // position model's 2^-8 (|d/dx| + |d/dy|); edge midpoints doubled the G-buffer's cost for
  // nothing.
  static constexpr int kShifts[kSlackShifts][2] = {{0, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  int n = 0;
  for (const auto& k : kShifts) {
    glm::dvec2 bs = bc;
    if ((k[0] != 0 || k[1] != 0) && !wb.at(scene, triangle, cx + s * k[0], cy + s * k[1], bs))
      continue;
    // Moved by the ray-cast difference from the raster's own barycentrics, so the centre value
    // is exactly the G-buffer's.
    const float b1 = bary.y + float(bs.x - bc.x), b2 = bary.z + float(bs.y - bc.y);
    out[n++] = interpolate_surface(scene, triangle, b1, b2);
  }
  return n;
}

vec4 texture_slack(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                   uint32_t triangle, const vec3& bary, const SurfaceMaterial& centre,
                   const SurfaceLods& lods) {
  // Untextured surfaces move too: the interpolated vertex normal (and COLOR_0's albedo) is an
  // attribute like the texture coordinates, read at the snapped sample point. On a dense smooth
  // mesh seen at a grazing angle that is a large change (scenes/scanned_statue.gltf at 64^2: 0.031
  // next to its silhouette); on flat-shaded triangles it is zero.
  SurfacePoint points[kSlackShifts];
  const int n = shifted_surface_points(scene, wb, x, row, triangle, bary, points);
  // Each slot's candidates; evaluation j takes the j-th of every slot (the last once a slot has
  // fewer), and each slack channel reads one slot only, so every candidate of every slot is seen.
  double cand[kTextureSlots][kMaxLodCandidates];
  int count[kTextureSlots], rounds = 1;
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    count[slot] = lod_candidates(lods.range[slot], cand[slot]);
    rounds = std::max(rounds, count[slot]);
  }
  vec4 slack(0.0f);
  // Each at both ends of where GL may decode sRGB (before or after filtering, GL 4.5 §8.24).
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < rounds; ++j)
      for (const bool after : {false, true}) {
        SlotLods l;
        for (int slot = 0; slot < kTextureSlots; ++slot)
          l.lambda[slot] = cand[slot][std::min(j, count[slot] - 1)];
        l.srgb_after_filter = after;
        slack = glm::max(slack, difference(evaluate_material(scene, points[i], l), centre));
      }
  return slack;
}

}  // namespace vct
