// Screen-space derivatives of the texture coordinates for the camera G-buffer's texture LOD
// (GL 4.5 §8.14.1): exact ones at the pixel centre for the reference's own lookup, and the
// admissible lambda interval GL may use instead (docs/compare.md, "Texture LOD"): its
// derivatives are 2x2-quad differences (coarse: one row / column of the quad for all four
// pixels; fine: the pixel's own), of values extrapolated on the triangle's plane at helper
// pixels, and rho may be approximated within §8.14.1's bounds.
#pragma once

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "scene/texture_lod.h"

namespace vct {

/// One triangle's perspective-correct barycentrics as a function of the window position (x, y up)
/// of a width x height view, defined on its whole plane (GL extrapolates at helper pixels):
/// b = h / (h0 + h1 + h2), h = M^-1 (x_ndc, y_ndc, 1), M's columns the vertices' clip-space
/// (x, y, w) (homogeneous rasterization). Double precision.
class ScreenBarycentrics {
 public:
  ScreenBarycentrics(const Scene& scene, uint32_t triangle, const mat4& view_proj, int width,
                     int height);
  bool valid() const { return valid_; }
  glm::dvec3 at(double wx, double wy) const;
  /// Exact d b / d wx and d b / d wy at (wx, wy).
  void derivatives(double wx, double wy, glm::dvec3& dx, glm::dvec3& dy) const;

 private:
  glm::dmat3 inv_{1.0};
  double width_ = 1.0, height_ = 1.0;
  bool valid_ = false;
};

/// The UV derivatives of `triangle` for barycentric derivatives (dx, dy).
UvDerivatives uv_derivatives(const Scene& scene, uint32_t triangle, const glm::dvec3& dx,
                             const glm::dvec3& dy);

/// For window pixel (px, py) (y up) covered by `triangle`: exact derivatives at its centre, and
/// the envelope over the exact ones and the quad differences of both rows (d/dx) and both
/// columns (d/dy) of its 2x2 quad (pixels (px & ~1, py & ~1) .. +1), each widened by the rho
/// approximation and the LOD precision (scene/texture_lod.h RhoBounds).
SurfaceLods pixel_lods(const Scene& scene, uint32_t triangle, const ScreenBarycentrics& sb, int px,
                       int py);

}  // namespace vct
