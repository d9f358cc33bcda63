// Occupancy differences on voxels that solid voxelization or surface thickening added
// (ref/stages/voxel_fill.h): a voxel opaque without fragments. Its opacity is a function of the
// surface occupancy (and the facing of the surface's triangles) on the six axis-aligned rays
// through it, nothing else, so a difference there is admissible exactly when one of those rays
// crosses a voxel whose surface differs between the two sides (docs/compare.md, "Filled voxels").
#pragma once

#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace vct::cmp {

/// Per voxel, 1 where the fragment counts differ: a surface on one side only, or another set of
/// triangles (so possibly other facing directions, which both fills read).
std::vector<uint8_t> surface_differences(const Volume& ref_fragments, const Volume& test_fragments);

/// Whether one of the six axis rays from voxel `i` (the voxel itself excluded) meets a voxel
/// set in `differs`.
bool ray_meets(const Volume& grid, const std::vector<uint8_t>& differs, size_t i);

}  // namespace vct::cmp
