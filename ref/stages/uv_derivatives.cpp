#include "stages/uv_derivatives.h"

#include <cmath>

namespace vct {

ScreenBarycentrics::ScreenBarycentrics(const Scene& scene, uint32_t triangle, const mat4& view_proj,
                                       int width, int height)
    : width_(double(width)), height_(double(height)) {
  const uvec3 t = scene.triangles[triangle];
  glm::dmat3 m;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec4 c = glm::dmat4(view_proj) * glm::dvec4(glm::dvec3(scene.positions[t[i]]), 1.0);
    m[i] = glm::dvec3(c.x, c.y, c.w);  // column i: vertex i
  }
  const double det = glm::determinant(m);
  valid_ = std::isfinite(det) && std::abs(det) > 1e-300;
  if (valid_) inv_ = glm::inverse(m);
}

glm::dvec3 ScreenBarycentrics::at(double wx, double wy) const {
  const glm::dvec3 h = inv_ * glm::dvec3(2.0 * wx / width_ - 1.0, 2.0 * wy / height_ - 1.0, 1.0);
  return h / (h.x + h.y + h.z);
}

void ScreenBarycentrics::derivatives(double wx, double wy, glm::dvec3& dx, glm::dvec3& dy) const {
  const glm::dvec3 h = inv_ * glm::dvec3(2.0 * wx / width_ - 1.0, 2.0 * wy / height_ - 1.0, 1.0);
  const double s = h.x + h.y + h.z;
  // d(h / s) = (dh s - h ds) / s^2, dh/dx_ndc = column 0 of M^-1, dx_ndc/dwx = 2 / width.
  const glm::dvec3 hx = inv_[0] * (2.0 / width_), hy = inv_[1] * (2.0 / height_);
  dx = (hx * s - h * (hx.x + hx.y + hx.z)) / (s * s);
  dy = (hy * s - h * (hy.x + hy.y + hy.z)) / (s * s);
}

UvDerivatives uv_derivatives(const Scene& scene, uint32_t triangle, const glm::dvec3& dx,
                             const glm::dvec3& dy) {
  UvDerivatives d;
  const uvec3 t = scene.triangles[triangle];
  const std::vector<vec2>* sets[2] = {&scene.uv0, &scene.uv1};
  for (int set = 0; set < 2; ++set) {
    const std::vector<vec2>& uv = *sets[set];
    if (uv.empty()) continue;
    glm::dvec2 ux(0.0), uy(0.0);
    for (int i = 0; i < 3; ++i) {
      ux += dx[i] * glm::dvec2(uv[t[i]]);
      uy += dy[i] * glm::dvec2(uv[t[i]]);
    }
    d.dx[set] = vec2(ux);
    d.dy[set] = vec2(uy);
  }
  return d;
}

SurfaceLods pixel_lods(const Scene& scene, uint32_t triangle, const ScreenBarycentrics& sb, int px,
                       int py) {
  SurfaceLods out;
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  if (!sb.valid()) return out;
  glm::dvec3 bx, by;
  sb.derivatives(double(px) + 0.5, double(py) + 0.5, bx, by);
  const UvDerivatives exact = uv_derivatives(scene, triangle, bx, by);
  // The quad's four centres; differences along its rows (d/dx) and columns (d/dy).
  const int qx = px & ~1, qy = py & ~1;
  glm::dvec3 b[2][2];  // [row][column]
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) b[r][c] = sb.at(double(qx + c) + 0.5, double(qy + r) + 0.5);
  UvDerivatives quad[2];  // quad[k]: row k's d/dx, column k's d/dy
  for (int k = 0; k < 2; ++k)
    quad[k] = uv_derivatives(scene, triangle, b[k][1] - b[k][0], b[1][k] - b[0][k]);
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref || size_t(ref->texture) >= scene.textures.size()) continue;
    const Texture& tex = scene.textures[size_t(ref->texture)];
    const TexelDerivatives e = texel_derivatives(tex, *ref, exact);
    out.exact.lambda[slot] = exact_lod(e);
    RhoBounds rho;
    rho.add_x(e.dx);
    rho.add_y(e.dy);
    for (const UvDerivatives& q : quad) {
      const TexelDerivatives t = texel_derivatives(tex, *ref, q);
      rho.add_x(t.dx);
      rho.add_y(t.dy);
    }
    out.range[slot] = rho.range();
  }
  return out;
}

}  // namespace vct
