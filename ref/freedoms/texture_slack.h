// How much a textured G-buffer value may legitimately move between two correct GL implementations:
// the range of the reference's own value over the sample-position shift that vertex snapping
// allows (the same 2^-8 pixel the interpolated-attribute tolerance uses, compare/tolerance.h) and
// over every lambda GL may use for the lookup (stages/uv_derivatives.h: quad differences, the
// approximated rho, LOD precision), at the lambdas of freedoms/lod_candidates.h (docs/compare.md,
// "G-buffer" and "Texture LOD"; dEQP's texture-lookup verifier takes the same approach).
#pragma once

#include <cstdint>

#include "core/math.h"
#include "freedoms/window_barycentrics.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/uv_derivatives.h"

namespace vct {

/// Channels of GBuffer::texture_slack, one per textured attribute: the largest |change| over the
/// attribute's channels; kSlackDirect: the direct light shaded from those attributes
/// (freedoms/direct_slack.h), filled once the direct light is; then kSlackAlphaTie, 1 where the
/// alpha test may go either way (freedoms/alpha_ties.h), which the comparison adds to its edge map
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

/// True when any of the material's slots has a texture.
bool is_textured(const Material& m);

/// Slack of the textured values at image pixel (x, row) (row 0 = top) whose closest surface is
/// `triangle` at barycentrics `bary` (b0, b1, b2) and whose reference value `centre` was looked
/// up at lods.exact: for each TextureSlackChannel, the largest |value - centre| over the centre
/// and the 4 shifts (+-s, +-s), s = kVertexSnapStep, each at every lod candidate of the
/// channel's texture slot. Without textures only the interpolated attributes (the vertex normal,
/// COLOR_0) move.
vec4 texture_slack(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                   uint32_t triangle, const vec3& bary, const SurfaceMaterial& centre,
                   const SurfaceLods& lods);

/// The same from the pixel's surface points `points` (shifted_surface_points' n points), for a
/// caller that needs them for more than the slack (add_gbuffer_freedoms: the tie range's plane).
vec4 texture_slack(const Scene& scene, const SurfacePoint* points, int n, uint32_t triangle,
                   const SurfaceMaterial& centre, const SurfaceLods& lods);

}  // namespace vct
