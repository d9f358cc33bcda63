// The PCF visibility a correct GL may compute for a voxel fragment anywhere the voxel raster's
// vertex snap may move it (freedoms/fragment_slack.h): a small parallelogram on its triangle. Every
// point of it is looked up, not only its corners: a texel edge or a depth tie crossed inside the
// parallelogram flips a tap that no corner shows. A tap's texel and its compare are decided
// together — the tap reads texel (i, j) only on the part of the parallelogram whose coordinate
// falls in it, and compares the depth of that part — so a plane never ties with its own stored
// depth the way independent margins on coordinate and depth would let it (docs/compare.md,
// "Voxel shading slack").
//
// Exact by construction: the world point is affine in the parallelogram's parameters (a, b), so
// are its clip coordinates, and every test a lookup makes — a coordinate past a texel edge, a
// depth past stored + bias, a direction on one cube face — is the sign of a linear function of
// (a, b) once multiplied by w > 0. Each region is the square clipped by half-planes; a depth
// (a ratio of two affine functions) takes its extremes over a convex region at its vertices. The
// lookup's own float arithmetic widens each test by freedoms/shadow_ties.h's margins.
#pragma once

#include "core/math.h"
#include "core/settings.h"
#include "freedoms/shadow_ties.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// The points centre + a * du + b * dv for a, b in [-1, 1] (world space).
struct SnapParallelogram {
  vec3 centre{0.0f};
  vec3 du{0.0f}, dv{0.0f};
  /// How far (per world axis) a correct GL's point may lie from the parallelogram's (a
  /// normal-offset lookup point's float arithmetic, shadow_ties.h's lookup_point_margin).
  double margin = 0.0;
};

/// [lo, hi] of one light's PCF visibility over every point of `q`: lo counts a tap lit only where
/// it is lit everywhere, hi where it is lit somewhere. Both compares: nearest (texelFetch, the
/// pipeline's own) and an engine's linear (shadow_compare = linear) with exact weights; the
/// weights' 8-bit freedom is a term of its own (freedoms/fragment_slack.cpp, linear_compare_slack).
VisibilityRange snap_visibility_range(const ShadowMap& map, const Light& light, const SnapParallelogram& q,
                                      const VctSettings& settings);

/// The same for surface points with unit normal n, each looked up at its normal-offset point
/// (stages/shadow_map.h): p + K w(p) n is affine in (a, b) like p, since w is, so the lookup points
/// form a parallelogram too (through each cube face the points may select for a point light),
/// with lookup_point_margin as its margin.
VisibilityRange snap_surface_visibility_range(const ShadowMap& map, const Light& light, const SnapParallelogram& q,
                                              const vec3& n, const VctSettings& settings);

}  // namespace vct
