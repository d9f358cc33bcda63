// Maps a transformed frame's stages back into the base scene's coordinates, so a metamorphic
// relation (docs/metamorphic.md) is one comparison of two stage sets of the same backend: the
// base frame as the reference, the mapped-back frame as the test.
#pragma once

#include "compare/stage_set.h"
#include "core/math.h"

namespace vct::cmp {

/// The scene and its volume moved by `t` (world units): every stage keeps its indices; only
/// gbuffer.position moves (minus t, exact on the lattice).
StageSet untranslated(const StageSet& test, const vec3& t);

/// The scene moved by `k` whole voxels inside a fixed volume (world shift `t` = k voxels): voxel
/// volumes are read back k voxels on (k / 2^L at mip level L; levels where that is not whole are
/// left out, and so are the cone-traced images, which sample those levels); voxels the shift
/// brought in from outside read 0. Image stages that read no voxels are kept (position minus t).
StageSet unshifted(const StageSet& test, const ivec3& k, const vec3& t, bool soft_shadows);

/// The scene and volume turned by turn90(axis): volumes read back through the turn's signed
/// index permutation (about z: base voxel (i, j, k) = turned voxel (N-1-j, i, k)), the six
/// directional mips of direction d from direction turn(d); gbuffer.position and gbuffer.normal
/// turned back. Shadow maps are left out: their up vector is fixed in the world (+z,
/// stages/shadow_map.cpp), so a turned light's map is turned in its own plane.
StageSet unturned(const StageSet& test, int axis);

/// The diffuse cone set is laid out in a tangent frame built from the normal by a fixed formula
/// (vct_shared.h frame_from_normal), which a turn does not commute with: only where the normal
/// is a coordinate axis and the tilted cones are a multiple of 4 (90-degree steps) is the turned
/// set the set of the turned normal. Elsewhere the stages that hold the diffuse cones
/// (image.indirect_diffuse, image.diffuse_term, image.final) are taken from `base`: not judged.
/// Returns how many pixels were left out.
size_t keep_turn_invariant_cones(StageSet& mapped, const StageSet& base, int diffuse_cone_count);

/// The turned-scene voxel that holds base voxel `i` of an n^3 grid.
ivec3 turned_voxel(const ivec3& i, int n, int axis);

/// Keeps only the stages both sets hold (a relation compares what it can map).
StageSet common_stages(const StageSet& a, const StageSet& with);

}  // namespace vct::cmp
