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
/// direction differ from the reference's by float rounding (~1e-6) and by the position snap
/// (the slack's 2^-8 voxel, a relative 1e-3 of a normal's change over a voxel at most); a margin
/// of 1e-2 is far above both.
constexpr float kBehindLightMargin = 1e-2f;

/// True when every correct GL computes this fragment's light with the reference's bits: an
/// untextured material (its emission a product of constants, correctly rounded on both sides),
/// no light reaching it by a margin (n.l < -kBehindLightMargin, outside a spot's outer cone or
/// beyond a light's range by that margin, where the shared falloffs are exactly 0) and no bounce.
/// Both backends then encode the same fixed-point integers (docs/compare.md, "Exact voxels").
bool fragment_light_is_exact(const Scene& scene, const VoxelFragment& f, const VctSettings& settings,
                             bool bounce);

/// Per voxel, 1 where every fragment is exact (fragment_light_is_exact), else 0.
Volume voxel_exactness(const Scene& scene, const Voxelization& vox, const VctSettings& settings, bool bounce);

}  // namespace vct
