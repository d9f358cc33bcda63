// Texture LOD in the voxelization pass (GL 4.5 §8.14 on the voxel grid's raster): each triangle is
// rasterized in its dominant-axis projection with one pixel per voxel (gl/shaders/voxelize.geom),
// so the fragment shader's implicit derivatives are the UV change per voxel step along the two
// in-plane axes. The projection is orthographic, the UV affine in it: quad differences (coarse or
// fine, helper pixels extrapolating on the plane) equal the exact derivatives, the same for every
// fragment of the triangle. GL's remaining freedom is the approximated rho and the LOD precision
// (docs/compare.md, "Texture LOD").
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "scene/surface.h"

namespace vct {

/// The lambdas of `triangle` in an n^3 voxelization of scene.volume.
SurfaceLods voxel_lods(const Scene& scene, uint32_t triangle, int n);

/// voxel_lods for every triangle (parallel, deterministic).
std::vector<SurfaceLods> voxel_lods_per_triangle(const Scene& scene, int n);

}  // namespace vct
