// Coverage ties carried through surface thickening (docs/pipeline.md, "Solid voxelization and
// surface thickening"; docs/compare.md, "Filled voxels"). Thickening makes a voxel opaque when a
// surface voxel up to k steps in front of it holds a triangle facing that way, so where the
// coverage ties (freedoms/coverage_ties.h) let a correct GL drop a surface voxel's fragments or
// make one a voxel away, the voxels behind it may be filled or not: scenes/regressions/
// seed-2572-small, a sliver's one fragment that llvmpipe wrote one voxel further along y (a
// coverage tie both ways), which moved the two voxels thickened behind it by one as well.
#pragma once

#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "stages/voxelize.h"

namespace vct {

/// voxel.occupancy_tie with the fills (add_coverage_ties already run on `vox`): 1 where a correct
/// GL's occupancy (surface or filled) may differ from the reference's. Without fills,
/// occupancy_ties(vox) itself. With the solid fill (not monotone in the surface: a triangle added
/// may close or open a ray), those ties less the voxels the reference fills, whose changes stay
/// the judge's counted fill-ray rule. With thickening by k alone, which is monotone in the surface and its
/// facing masks: a voxel may be occupied when it may hold a fragment or is thickened from the
/// largest admissible surface (the reference's fragments and every fragment it may add, with their
/// facings), and may be empty when it may hold none and is not thickened from the smallest (the
/// fragments none of the ties may drop); it is a tie when both hold.
Volume occupancy_ties_with_fills(const Scene& scene, const Voxelization& vox, const VctSettings& settings);

}  // namespace vct
