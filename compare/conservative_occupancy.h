// The judge of a conservative voxelization mode (settings.conservative_raster: the GL geometry-
// shader mode, or the driver's hardware conservative rasterizer) against the CPU's exact
// triangle-box voxelizer: every exact voxel present (a missing voxel FAILs, named), extra voxels
// only where a triangle meets the voxel's box dilated by the mode's stated over-estimation.
// The bound of each mode and its derivation: docs/compare.md, "Conservative voxelization".
#pragma once

#include <array>
#include <string>
#include <vector>

#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/math.h"
#include "core/volume.h"
#include "stages/backend_facts.h"
#include "stages/voxelize.h"  // triangle_meets_box, kConservativeArithmetic

namespace vct {
struct Scene;
}

namespace vct::cmp {

/// One row per mode (the numbers are written into the verdict's bound text).
struct ConservativeBound {
  std::string mode;    // "gs" | "nv" | "intel"
  double over = 0.0;   // voxels: an extra voxel is admitted where a triangle meets its box grown by this
  double under = 0.0;  // voxels: a missing voxel is a tie only where no triangle meets its box shrunk by this
  std::string source;  // the freedom the numbers stand for
};

/// The bound of the mode `facts` say ran; mode "" when none did. A hardware mode without its
/// snapping precision (conservative_snap_bits < 1) is an InputError naming `where`.
ConservativeBound conservative_bound(const BackendFacts& facts, const std::string& where);

using VoxelTriangle = std::array<glm::dvec3, 3>;

/// The scene's triangles in voxel space of an n^3 grid (stages/voxelize.h to_voxel_space).
std::vector<VoxelTriangle> voxel_space_triangles(const Scene& scene, int n);

/// Does a triangle meet voxel (x, y, z)'s unit box grown by `grow` on every side (shrunk when
/// negative)?
bool any_triangle_meets_voxel(const std::vector<VoxelTriangle>& tris, const ivec3& voxel, double grow);

/// Occupancy `test` (1 channel or RGBA: > 0 in the last channel) against the exact set `exact`.
/// `tris` empty: extra voxels cannot be checked (no scene) and make the verdict warn.
StageVerdict judge_conservative_occupancy(const Volume& exact, const Volume& test,
                                          const std::vector<VoxelTriangle>& tris,
                                          const ConservativeBound& bound, size_t worst_n);

/// Replaces `rep`'s voxel.occupancy verdict when the test set says a conservative mode ran
/// (test.facts.conservative_mode): the reference must have voxelized exactly (settings voxelizer
/// = conservative); `scene` (may be null) gives the triangles for the extra-voxel check.
void judge_conservative_mode(Report& rep, const StageSet& reference, const StageSet& test, const Scene* scene,
                             size_t worst_n);

}  // namespace vct::cmp
