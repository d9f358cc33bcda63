// Whole-scene transforms for the metamorphic checks (docs/metamorphic.md): moves, 90-degree turns
// and light scaling applied to everything a frame reads (vertices, normals, tangents, lights,
// camera, particle emitters, the voxel volume), chosen so that they are exact in binary floating
// point: a power-of-two voxel, positions on a lattice of 1/64 voxel, turns by swapping and
// negating coordinates, scaling by 2.
#pragma once

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// Subdivisions of a voxel the lattice positions snap to (2^6: far below any raster or voxel
/// precision, yet lattice sums stay exact up to 2^18 voxels from the origin).
inline constexpr float kLatticeStepsPerVoxel = 64.0f;

/// The scene in a volume of its own for the checks: size a power of two, origin 1/2, 1/4,
/// 1/8 of a lattice step below a multiple of the voxel (no lattice position on a voxel face, no
/// 45-degree lattice edge through a voxel edge), the scene inside with one free voxel on every side
/// plus `room_voxels` free voxels on the + side of each axis (room for a shift), and every position
/// (vertices, lights, camera, emitters) rounded to 1/64 voxel, so that moving by whole voxels and
/// turning are exact.
Scene on_voxel_lattice(const Scene& scene, int grid, int room_voxels);

/// Every position moved by `t` (world units); the voxel volume too when `move_volume`.
Scene translated(const Scene& scene, const vec3& t, bool move_volume);

/// A +90 degree turn about coordinate axis `axis` (0 = x, 1 = y, 2 = z) through the world
/// origin, right-handed (about z: +x -> +y, +y -> -x): a signed permutation of coordinates.
vec3 turn90(const vec3& v, int axis);
/// The inverse turn (-90 degrees about the same axis).
vec3 unturn90(const vec3& v, int axis);

/// The scene (and its voxel volume, as the cube the turned corners span) turned by turn90.
Scene turned90(const Scene& scene, int axis);

/// Every source of light times `factor`: material emission, spot intensities, particle colours.
Scene light_scaled(const Scene& scene, float factor);

}  // namespace vct
