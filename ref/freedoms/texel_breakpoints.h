// Where a NEAREST lookup changes texel inside the square a vertex snap may move a fragment over.
//
// A fragment's light over the snap's parallelogram is smooth except where a NEAREST lookup (GL 4.5
// §8.14.2: the texel containing the sample point) jumps from one texel to the next. Within each
// texel's piece the light is smooth over a few thousandths of a voxel, so its extremes lie on the
// pieces' corners: the square's corners, the texel lines' crossings of the square's edges, and the
// texel corners inside it; a point just inside each piece at each of its corners reaches them.
// The square's corners alone miss a jump across it: on seed 229 a texel line crossed the square
// 0.3 of its width from one side, and the lit texel's brightest point lay on that line, 0.015
// above every corner's light (docs/compare.md, "Voxel shading slack").
#pragma once

#include <cstddef>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// An affine map from window offsets (du, dv) to texel coordinates of one level (texel i covers
/// [i, i + 1)): texels = at_centre + du * per_u + dv * per_v.
struct TexelMap {
  glm::dvec2 at_centre{0.0};
  glm::dvec2 per_u{0.0}, per_v{0.0};
};

/// Window offsets in [-r, r]^2 that reach every texel piece's corners: for each texel the square
/// meets, its piece (the square cut by the texel's four lines, a convex polygon) and a point a
/// sixty-fourth of the way from each of the piece's corners to its centre, so inside the piece
/// however thin (a texel corner just inside the square's edge leaves a sliver that points a fixed
/// distance off the lines miss). Appends to `out`; false (and nothing appended) when there would be
/// more than `cap` points.
bool texel_breakpoints(const TexelMap& map, double r, size_t cap, std::vector<glm::dvec2>& out);

/// The maps of the level(s) a lookup of `texture` at `lambda` reads when it filters NEAREST within
/// a level (none for LINEAR), for texture coordinates `uv` at the centre moving by `per_u`, `per_v`
/// per unit window offset; appended to `out`.
void append_nearest_level_maps(const Texture& texture, bool srgb, double lambda, const glm::dvec2& uv,
                               const glm::dvec2& per_u, const glm::dvec2& per_v, std::vector<TexelMap>& out);

}  // namespace vct
