// How much a textured G-buffer value may legitimately move between two correct rasterizers: the
// reference's own value over the sample-position shift that vertex snapping allows (the same
// 2^-8 pixel the interpolated-attribute tolerance uses, compare/tolerance.h). GL does not mip the
// material textures (LINEAR at level 0, gl/gl_scene.cpp), so under minification one pixel spans
// many texels and a 1e-3 pixel shift moves the bilinear sample across texel steps: 0.02 texels
// at 16 texels per pixel on demo_room's back wall at 64^2 (docs/compare.md, "G-buffer").
#pragma once

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"

namespace vct {

/// Largest sample shift (pixels, per axis) the slack covers: one sub-pixel step of the snapping
/// grid on each axis (kSubpixelBits = 8), as the position model's 2^-8 (|d/dx| + |d/dy|).
constexpr double kTextureSlackShift = 1.0 / 256.0;

/// Channels of GBuffer::texture_slack, one per textured attribute: the largest |change| over the
/// attribute's channels; then kSlackAlphaTie, 1 where the alpha test may go either way
/// (stages/alpha_ties.h), which the comparison adds to its edge map (docs/compare.md,
/// "Alpha-mask ties").
enum TextureSlackChannel : int {
  kSlackNormal = 0,
  kSlackAlbedo,
  kSlackMaterial,
  kSlackEmission,
  kSlackAlphaTie,
  kSlackChannels
};

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

/// Slack of the textured values at image pixel (x, row) (row 0 = top) whose closest surface is
/// `triangle` at barycentrics `bary` (b0, b1, b2): for each TextureSlackChannel, the largest
/// |value(shifted) - value(centre)| over the 4 shifts (+-s, +-s) with s = kTextureSlackShift.
/// Zero for materials without textures.
vec4 texture_slack(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                   const vec3& bary, const SurfaceMaterial& centre);

}  // namespace vct
