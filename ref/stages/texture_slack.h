// How much a textured G-buffer value may legitimately move between two correct GL implementations:
// the range of the reference's own value over the sample-position shift that vertex snapping
// allows (the same 2^-8 pixel the interpolated-attribute tolerance uses, compare/tolerance.h) and
// over every lambda GL may use for the lookup (stages/uv_derivatives.h: quad differences, the
// approximated rho, LOD precision). A trilinear lookup is linear in lambda between integer levels
// (and piecewise constant for *_MIPMAP_NEAREST, stepping at k + 1/2), so its values over
// [lo, hi] are spanned by those at lo, hi and every integer in between (docs/compare.md,
// "G-buffer" and "Texture LOD"; dEQP's texture-lookup verifier takes the same approach).
#pragma once

#include "core/math.h"
#include "scene/scene.h"
#include "stages/raster.h"
#include "scene/surface.h"
#include "scene/texture_lod.h"
#include "stages/uv_derivatives.h"

namespace vct {

/// Largest sample shift (pixels, per axis) the slack covers: one sub-pixel step of the snapping
/// grid on each axis (kSubpixelBits = 8), as the position model's 2^-8 (|d/dx| + |d/dy|).

/// Channels of GBuffer::texture_slack, one per textured attribute: the largest |change| over the
/// attribute's channels; kSlackDirect: the direct light shaded from those attributes
/// (stages/direct_slack.h), filled once the direct light is; then kSlackAlphaTie, 1 where the
/// alpha test may go either way (stages/alpha_ties.h), which the comparison adds to its edge map
/// (docs/compare.md, "Alpha-mask ties").
enum TextureSlackChannel : int {
  kSlackNormal = 0,
  kSlackAlbedo,
  kSlackMaterial,
  kSlackEmission,
  kSlackDirect,
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

/// The sample points the slack considers: the pixel centre and the four (+-s, +-s) shifts.
constexpr int kSlackShifts = 5;

/// Sub-texel weight precision: GL leaves the filter weights' precision open (§8.14.2); current
/// GPUs keep 8 fractional bits (D3D11 functional spec §7.18.16.1, dEQP LookupPrecision), so a
/// weight may be the exact weight of a point up to 2^-8 texel away on each axis of each level.
constexpr float kSubtexelShift = 1.0f / 256.0f;
constexpr int kTexelShifts = 5;
/// Shift k of the lookup's sample point, in texels: k = 0 none, 1..4 the (+-s, +-s) corners
/// (a bilinear lookup is linear in each weight, so its extremes over the square are at corners).
inline vec2 texel_shift(int k) {
  const float s = kSubtexelShift;
  return k == 0 ? vec2(0.0f) : vec2((k & 1) ? s : -s, (k & 2) ? s : -s);
}

/// Precision of a filtered 8-bit UNORM lookup: GL leaves the filtering arithmetic open, and a
/// result may be off by one step of the format (dEQP's texture verifiers take the colour threshold
/// of an 8-bit format as one step; llvmpipe filters RGBA8 in 8-bit integers). A normal map lit at
/// a grazing angle turns that step into a large relative change of n.l (docs/compare.md, "Voxel
/// shading slack").
constexpr float kUnorm8Step = 1.0f / 255.0f;
constexpr int kUnorm8Corners = 8;
/// Corner k of the cube [-kUnorm8Step, kUnorm8Step]^3 (the light is nearly linear-fractional in
/// the texel, so its extremes over the cube lie at corners).
inline vec3 unorm8_corner(int k) {
  const float s = kUnorm8Step;
  return vec3((k & 1) ? s : -s, (k & 2) ? s : -s, (k & 4) ? s : -s);
}

/// True when any of the material's slots has a texture.
bool is_textured(const Material& m);

/// The surface points of `triangle` at image pixel (x, row)'s centre (raster barycentrics `bary`,
/// so the first is exactly the G-buffer's) and at its (+-s, +-s) shifts, s = kVertexSnapStep;
/// returns how many (shifts whose view ray misses the plane are left out).
int shifted_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                           uint32_t triangle, const vec3& bary, SurfacePoint out[kSlackShifts]);

/// The lambdas whose lookups span every value an admissible lambda in `range` can give: lo, hi,
/// each integer strictly between, and (when magnification and minification both lie in the
/// range) the minified lookup at lambda -> 0+, which differs from the magnified one when the
/// filters do. At most kMaxLodCandidates (the range is then clipped to its first ones; ranges
/// are a few tenths of a level wide).
constexpr int kMaxLodCandidates = 8;
int lod_candidates(const LodRange& range, double out[kMaxLodCandidates]);

/// Slack of the textured values at image pixel (x, row) (row 0 = top) whose closest surface is
/// `triangle` at barycentrics `bary` (b0, b1, b2) and whose reference value `centre` was looked
/// up at lods.exact: for each TextureSlackChannel, the largest |value - centre| over the centre
/// and the 4 shifts (+-s, +-s), s = kVertexSnapStep, each at every lod candidate of the
/// channel's texture slot. Without textures only the interpolated attributes (the vertex normal,
/// COLOR_0) move.
vec4 texture_slack(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                   uint32_t triangle, const vec3& bary, const SurfaceMaterial& centre,
                   const SurfaceLods& lods);

}  // namespace vct
