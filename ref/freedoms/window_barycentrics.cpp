#include "freedoms/window_barycentrics.h"

#include <cmath>

#include "stages/raster.h"  // kVertexSnapStep

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
// The barycentrics (b1, b2) of `triangle` at image pixel (x, row)'s centre and at its (+-s, +-s)
// shifts, each passed to emit(b1, b2); returns how many (shifts whose view ray misses the plane
// are left out).
template <typename Emit>
int for_each_shifted_sample(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                            const vec3& bary, Emit&& emit) {
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
    emit(n++, bary.y + float(bs.x - bc.x), bary.z + float(bs.y - bc.y));
  }
  return n;
}
}  // namespace

int shifted_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                           uint32_t triangle, const vec3& bary, SurfacePoint out[kSlackShifts]) {
  return for_each_shifted_sample(scene, wb, x, row, triangle, bary, [&](int k, float b1, float b2) {
    out[k] = interpolate_surface(scene, triangle, b1, b2);
  });
}

int shifted_surface_positions(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                              uint32_t triangle, const vec3& bary, vec3 out[kSlackShifts]) {
  return for_each_shifted_sample(scene, wb, x, row, triangle, bary, [&](int k, float b1, float b2) {
    out[k] = interpolated_position(scene, triangle, b1, b2);
  });
}

}  // namespace vct
