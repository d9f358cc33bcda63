// How far a voxel fragment's light may legitimately move between the reference and a correct GL:
// the shading freedoms the GL specification leaves to the voxelization pass, each tried on the
// reference's own fragment (docs/compare.md, "Voxel shading slack"):
//   - position: vertices snap to a 2^-8 pixel grid of the voxel raster (GL_SUBPIXEL_BITS 8), so
//     the attributes at a pixel centre are those of a point up to 2^-8 voxel away on each in-plane
//     axis of the dominant-axis projection — more where the centre lies outside the triangle and
//     the attributes are extrapolated (voxel_snap_reach). That moves the fragment along its
//     triangle: the falloff and textures shift, and a PCF tap flips anywhere in the parallelogram
//     it may reach (freedoms/snap_visibility.h), not only at its corners;
//   - texture LOD: every lambda a correct GL may use (stages/voxel_lod.h);
//   - sub-texel weights: filter weights with 8 fractional bits (freedoms/lookup_precision.h);
//   - lookup precision: a filtered normal-map texel (8-bit UNORM) may be one format step off, and
//     an sRGB texel's decode half a step of its encoding (core/precision.h, srgb-decode).
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/inject.h"
#include "stages/raster.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// Largest pixel-centre shift of the voxel raster the slack covers, in voxels per in-plane axis:
/// one sub-pixel step of the snapping grid (as the raster stages' 2^-8 pixel, compare/tolerance.h).

/// How far, in voxels per in-plane axis, the snap may move the point whose attributes GL
/// interpolates for fragment f: kVertexSnapStep x sum |l_i| / (1 - kVertexSnapStep G), l the
/// fragment's barycentrics at its pixel centre (extrapolated when the centre is outside) and G the
/// sum of their window-space gradients' magnitudes (docs/compare.md, "Voxel shading slack").
/// +infinity for a sliver (kVertexSnapStep G >= 1/2) or a triangle seen edge-on in its window.
double voxel_snap_reach(const Scene& scene, int n, const VoxelFragment& f);

/// Where GL may write fragment f along its dominant axis (freedoms/coverage_ties.h): the axis, the
/// reference's voxel-space depth there (relative to vertex 0, as voxelize.frag interpolates it)
/// and how far GL's may lie from it. The point GL interpolates may be voxel_snap_reach away on
/// each window axis, which moves the depth by the plane's in-window gradient times that reach;
/// GL's barycentrics are floats (a few roundings of values in [-1, 2]: 2^-20 each, with room),
/// times the vertices' depth differences. +infinity for a sliver (no bound on the reach).
struct VoxelDepthTie {
  int axis = 0;
  double depth = 0.0, margin = 0.0;
};
VoxelDepthTie voxel_depth_tie(const Scene& scene, int n, const VoxelFragment& f);

/// Per fragment, how far a correct GL's light may lie from the reference's (largest over RGB): the
/// sum, each taken where the reference sits, of the largest changes over the snap square (its
/// corners and every NEAREST texel piece's corners, freedoms/texel_breakpoints.h), over each group
/// of material freedoms (every admissible lambda x sub-texel shift x sRGB staging; the normal
/// texel's 8-bit precision; the other bitangent; the sRGB decode's precision), over the shadow
/// visibility anywhere in the square (at the largest unshadowed light GL's fragment may have), and
/// hard_spot_slack. The freedoms are independent; each change is taken light by light on the
/// signed cosine (freedoms/light_terms.h), so the sum bounds their combination by the triangle
/// inequality to first order (docs/compare.md, "Voxel shading slack").
std::vector<float> fragment_shading_slack(const Scene& scene, const Voxelization& vox,
                                          const std::vector<ShadowMap>& maps,
                                          const VctSettings& settings,
                                          const BounceLight* bounce = nullptr);

/// The hard-spot term of a fragment's slack (grid n): where a hard spot's edge passes within its
/// float tie of the fragment (direct_ties.h, hard_spot_lit_sample), the lit side's unshadowed
/// diffuse light, summed over such spots; 0 elsewhere. fragment_shading_slack adds it.
float hard_spot_slack(const Scene& scene, int n, const VoxelFragment& f, const VctSettings& settings);

/// Per voxel, the mean of its fragments' slacks: the voxel's mean moves by at most that.
Volume voxel_shading_slack(const Voxelization& vox, const std::vector<float>& slack);

}  // namespace vct
