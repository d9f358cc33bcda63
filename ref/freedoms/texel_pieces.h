// The camera G-buffer's NEAREST texel pieces under the snap. A pixel's sample may sit anywhere in
// the square [-s, s]^2 around its centre (s = kVertexSnapStep, freedoms/window_barycentrics.h), and
// a NEAREST lookup (GL 4.5 §8.14.2) changes texel wherever a texel line crosses that square: where
// a texture is minified far below its resolution the square spans several texels, and its four
// corners miss the ones between them (medium hunt seed 259: a 5 x 32 normal map, NEAREST without
// mipmaps, on a triangle 114 texel rows long seen over a few pixels; llvmpipe read a texel no
// corner reads). The points below reach every piece, as the voxel shading slack's
// (freedoms/texel_breakpoints.h), so the texture slack, the direct slack and the tie range's
// alternatives see every texel GL may read (docs/compare.md, "Texture LOD", the G-buffer bullet).
#pragma once

#include <cstdint>
#include <vector>

#include "freedoms/window_barycentrics.h"
#include "scene/scene.h"
#include "scene/surface.h"

namespace vct {

/// Surface points of `triangle` inside image pixel (x, row)'s snap square, one inside each
/// NEAREST texel piece corner of every texture level its lookups may read at the lambdas of `lods`
/// (each slot's candidates, freedoms/lod_candidates.h), appended to `out`; barycentrics moved by
/// the ray-cast difference from `bary`, as shifted_surface_points'. Nothing for an untextured
/// material or a square inside one texel of every level. Beyond a cap, a 16 x 16 grid over the
/// square stands in (a texture hundreds of times finer than the snap, as in fragment_slack.cpp).
void texel_piece_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                        const vec3& bary, const SurfaceLods& lods, std::vector<SurfacePoint>& out);

/// Every point a G-buffer freedom evaluates a textured value at: shifted_surface_points' (the
/// centre and the four corners) first, then texel_piece_points'. Replaces `out`'s contents and
/// returns how many of them are shifted_surface_points' (0 where the centre's ray misses the plane).
int snap_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                        const vec3& bary, const SurfaceLods& lods, std::vector<SurfacePoint>& out);

}  // namespace vct
