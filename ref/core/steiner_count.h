// How many voxels a triangle meets, expected over where the grid falls (issue 37: the memory
// estimate's fragment lists follow the mesh, not 8 N^2; docs/performance.md, "Validate's memory").
#pragma once

#include <cstdint>

#include "core/math.h"

namespace vct {

/// One triangle's terms of Steiner's formula, in the units of its coordinates: the volume of its
/// Minkowski sum with an axis-aligned cube of edge h (a zonotope: the sum of three segments) is
///   h * A (|n_x| + |n_y| + |n_z|) + h^2 (e_x + e_y + e_z) + h^3,
/// A the area, n the unit normal, e the bounding box's extents. A grid of cubes of edge h placed
/// at random meets the triangle in that volume / h^3 cubes on average: the conservative
/// voxelizer's fragments of it ("one per (triangle, voxel) it meets", stages/voxelize.h).
struct SteinerTerms {
  double projected_area = 0;  // A (|n_x| + |n_y| + |n_z|): the areas of its three axis projections
  double extent = 0;          // e_x + e_y + e_z
};

SteinerTerms steiner_terms(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// The expected voxels met by `triangles` triangles whose terms sum to `sums`, in a grid of `n`
/// voxels per edge of a cube of edge 1 (the sums in units of the cube's edge).
double steiner_voxels(const SteinerTerms& sums, uint64_t triangles, int n);

}  // namespace vct
