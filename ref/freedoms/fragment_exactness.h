// Which voxels GL must reproduce bit for bit: those whose fragments' light no freedom of the GL
// specification reaches (docs/compare.md, "Exact voxels"). With the fixed-point reduction both
// backends then sum the same integers and round them the same way, so the reduction is judged
// exactly there, apart from the shading freedoms (freedoms/fragment_slack.h) everywhere else.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// n.l below which no correct GL lets a light reach a fragment: GL's interpolated normal and light
/// direction differ from the reference's by float rounding (~1e-6), far below it. The position
/// snap is not in it: it is taken over the fragment's snap square (freedoms/snap_window.h), since
/// on a triangle much smaller than a voxel whose vertex normals differ, 2^-8 voxel moves the
/// barycentrics by ~1/20 and the normal by more than the margin (large hunt seed 116).
constexpr float kBehindLightMargin = 1e-2f;

/// True when every correct GL computes this fragment's light with the reference's bits: an
/// untextured material (its emission a product of constants, correctly rounded on both sides),
/// no light reaching it by a margin anywhere in its snap square at grid `grid` (n.l below
/// -kBehindLightMargin, outside a spot's outer cone or beyond a light's range by that margin,
/// where the shared falloffs are exactly 0; a sliver whose snap has no bound is exact only in a
/// scene without lights) and no bounce. Both backends then encode the same fixed-point integers
/// (docs/compare.md, "Exact voxels").
bool fragment_light_is_exact(const Scene& scene, const VoxelFragment& f, const VctSettings& settings, int grid,
                             bool bounce);

/// Per voxel, 1 where every fragment is exact (fragment_light_is_exact), else 0.
Volume voxel_exactness(const Scene& scene, const Voxelization& vox, const VctSettings& settings, bool bounce);

}  // namespace vct
