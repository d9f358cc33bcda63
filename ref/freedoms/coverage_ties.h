// Coverage ties of the voxel raster: which fragments a correct GL may make or not make.
// GL leaves vertex snapping to the implementation (GL 4.5 §14.6.1; GL_SUBPIXEL_BITS 8), so each
// snapped window coordinate of the dominant-axis projection may be one 2^-8 pixel step off the
// reference's. That moves a triangle's edge at a sample by at most what moving the sample by one
// of the four (+-2^-8, +-2^-8) corner shifts moves it (freedoms/gbuffer_ties.h derives this for the
// camera raster; the voxel raster is the same rasterizer with one pixel per voxel). A fragment is a
// covered pixel (any MSAA sample), so a triangle whose coverage of a voxel's pixel differs between
// the centre samples and any shifted ones may or may not add its fragment there: the set of
// fragments GL averages in that voxel may differ from the reference's even at the same count
// (atrium, grid 32, voxel (7, 19, 9): a shadowed fragment of one triangle swapped for a lit one
// of another, GL's mean 6 % above the reference's; docs/compare.md, "Voxel shading slack").
// The same snap moves the point whose depth along the dominant axis GL floors to pick the voxel,
// so a fragment within that reach of a voxel boundary may land in the voxel beyond it (the
// built-in scene, grid 32, voxel (14, 18, 11): a fragment at depth 14.99984 that GL wrote to
// voxel 15, leaving the other fragment's light alone there, twice the reference's mean).
// The reference widens the voxel's slack to every mean such a set admits.
#pragma once

#include <vector>

#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "stages/inject.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// Fills vox.may_drop and vox.may_add by voxelizing the scene again with the sample positions
/// moved by each of the four (+-2^-8, +-2^-8) pixel shifts: a fragment missing from any shifted
/// voxelization may be dropped, one present in any but not in `vox` may be added; and a fragment
/// whose depth lies within its depth margin of a voxel boundary may move to the voxel beyond it;
/// and a fragment whose alpha test may flip may be dropped or added (freedoms/voxel_alpha_ties.h).
/// For the conservative voxelizer (vox.samples empty) the ties are the triangles meeting a voxel
/// box within kConservativeArithmetic of its faces, as GL's conservative modes' own arithmetic
/// may decide them either way (the gs mode's whole bound; a hardware mode over-estimates more).
void add_coverage_ties(const Scene& scene, Voxelization& vox);

/// 1 per voxel where the coverage ties (add_coverage_ties, already run on `vox`) let a correct GL's
/// occupancy differ from the reference's: every fragment in the voxel may drop, or a fragment GL
/// may make lands in a voxel `vox` leaves empty (VoxelGrid::occupancy_tie).
Volume occupancy_ties(const Voxelization& vox);

/// Per voxel (channels lo, hi) the fewest and the most fragments a correct GL may make there: the
/// reference's count less those in `may_drop`, plus those of `may_add` landing there
/// (VoxelGrid::fragment_count_range). Empty when add_coverage_ties has not run.
Volume fragment_count_ranges(const Voxelization& vox);

/// Widens `slack` (per voxel, freedoms/fragment_slack.h's voxel_shading_slack) by the fragment sets
/// the coverage ties admit: where a voxel's set may change, its slack becomes the largest
/// distance, over RGB, between the reference's mean and the mean of any admissible set, each
/// fragment taken at its light +- its own shading slack (the largest mean adds the certain
/// fragments and a prefix of the uncertain ones sorted by light, the smallest likewise). Values
/// and slacks of the fragments that may be added are evaluated here as inject_and_reduce would.
/// `exact` (voxel.exact) is cleared where the set may change: the same integers need the same
/// fragments.
void widen_for_coverage_ties(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                             const std::vector<float>& fragment_slack, const std::vector<ShadowMap>& maps,
                             const VctSettings& settings, const BounceLight* bounce, Volume& slack,
                             Volume& exact);

/// The interval, per channel, of the means over every set made of all of `certain` and any subset
/// of `uncertain` (not empty when `certain` is): lo from value - slack, hi from value + slack.
/// Exposed for tests.
struct MeanRange {
  double lo = 0.0, hi = 0.0;
};
MeanRange admissible_mean_range(const std::vector<double>& certain_lo, const std::vector<double>& certain_hi,
                                std::vector<double> uncertain_lo, std::vector<double> uncertain_hi);

}  // namespace vct
