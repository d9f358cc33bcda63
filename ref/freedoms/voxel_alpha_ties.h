// Alpha-mask ties of the voxel raster. The voxelization pass discards a fragment whose alpha is
// below the material's cutoff (voxelize.frag, as every pass that rasterizes), and the alpha a
// correct GL computes there is free by the bilinear weights' precision and the sample's snapping
// (freedoms/alpha_ties.h; docs/compare.md, "Alpha-mask ties"): a fragment within that freedom of
// the cutoff may be kept or discarded whichever the reference did. The voxel raster is
// orthographic, so the snap's reach in barycentrics is the same at every pixel of a triangle.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "stages/voxelize.h"

namespace vct {

/// For a GPU-rule voxelization `vox` of an alpha-tested scene: marks in `may_drop` (same order as
/// vox.fragments) the kept fragments whose alpha test may flip, and appends to `may_add` the
/// fragments the reference discarded whose test may flip. Nothing for a scene without alpha tests
/// or the conservative voxelizer (vox.samples empty).
void add_voxel_alpha_ties(const Scene& scene, const Voxelization& vox, std::vector<uint8_t>& may_drop,
                          std::vector<VoxelFragment>& may_add);

}  // namespace vct
