// Opacity added to empty base-level voxels by two of issue 17's artifact fixes (docs/pipeline.md,
// "Solid voxelization and surface thickening"): the interior of closed geometry
// (settings.solid_voxelization) and k voxels behind each surface (settings.surface_thickening_voxels).
// Both are decided from the surface occupancy alone (voxels holding at least one fragment), so the
// two fills are independent and their union is what the grid gets: A = 1, RGB left as it is.
#pragma once

#include <cstdint>
#include <vector>

#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "stages/voxelize.h"

namespace vct {

/// Direction (AnisoDir order: +x, -x, +y, -y, +z, -z) a triangle faces along its dominant axis
/// (voxelize.h dominant_axis): 2 * axis, +1 when the winding normal's component there is negative.
int facing_direction(const vec3& v0, const vec3& v1, const vec3& v2);

/// Per voxel, a 6-bit mask of the facing directions of the triangles whose fragments it holds.
std::vector<uint8_t> facing_masks(const Scene& scene, const Voxelization& vox);

/// 1 where an empty voxel is inside: each of its six axis-aligned rays meets a surface voxel
/// before leaving the grid, and that first surface voxel holds no triangle facing back along the
/// ray (toward the voxel). The interior of a closed mesh whose winding faces outward fills; a room
/// whose walls face inward does not.
std::vector<uint8_t> enclosed_voxels(const std::vector<uint8_t>& surface, const std::vector<uint8_t>& masks,
                                     int n);

/// 1 where an empty voxel is among the `k` voxels behind a surface voxel (opposite a direction
/// in its facing mask).
std::vector<uint8_t> thickened_voxels(const std::vector<uint8_t>& surface, const std::vector<uint8_t>& masks,
                                      int n, int k);

/// Sets A = 1 in `radiance` (4 channels, N^3) on the voxels the settings' fills add.
/// Returns how many voxels were added.
int64_t fill_voxels(const Scene& scene, const Voxelization& vox, const VctSettings& settings, Volume& radiance);

}  // namespace vct
