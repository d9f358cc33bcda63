// Where a G-buffer pixel's sample may land under vertex snapping: GL leaves snapping to the
// implementation (GL 4.5 §14.6.1), so the sample may sit up to one sub-pixel step (kVertexSnapStep,
// stages/raster.h) off the reference's on each axis. The freedoms that move a textured or
// interpolated value by that shift (texture slack, alpha ties, direct slack) evaluate the surface at
// the centre and at the shifted points this file finds (docs/compare.md, "G-buffer").
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"

namespace vct {

/// Window-space ray caster for one view: perspective-correct barycentrics of a triangle's plane
/// at any window point (extrapolated beyond the triangle's edges, as GL interpolates).
class WindowBarycentrics {
 public:
  WindowBarycentrics(const mat4& view_proj, int width, int height);
  /// (b1, b2) of `triangle` at window point (wx, wy), y up; false if the ray misses its plane.
  bool at(const Scene& scene, uint32_t triangle, double wx, double wy, glm::dvec2& b) const;
  int height() const { return height_; }

 private:
  glm::dmat4 inv_view_proj_;
  int width_, height_;
};

/// The sample points the slack considers: the pixel centre and the four (+-s, +-s) shifts.
constexpr int kSlackShifts = 5;

/// The surface points of `triangle` at image pixel (x, row)'s centre (raster barycentrics `bary`,
/// so the first is exactly the G-buffer's) and at its (+-s, +-s) shifts, s = kVertexSnapStep;
/// returns how many (shifts whose view ray misses the plane are left out).
int shifted_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                           uint32_t triangle, const vec3& bary, SurfacePoint out[kSlackShifts]);

/// Only the positions of shifted_surface_points' points (the same bits, scene/surface.h
/// interpolated_position): what the G-buffer's position and depth ranges read.
int shifted_surface_positions(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                              uint32_t triangle, const vec3& bary, vec3 out[kSlackShifts]);

}  // namespace vct
