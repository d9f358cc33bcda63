// Voxelization of the scene's triangles into the N^3 grid of scene.volume, two ways:
//  (a) conservative: the exact set of voxels containing a point of the triangle (separating-axis
//      triangle/box test against half-open voxel boxes);
//  (b) the GPU's rule: dominant-axis projection as the seed's geometry shader, MSAA sample
//      coverage with the standard patterns, depth along the axis from the interpolated position.
// Comparing them gives the "holes" (voxels (a) has and (b) misses). docs/pipeline.md,
// "Voxelization".
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "stages/raster.h"

namespace vct {

/// A surface sample that lands in one voxel: where light injection evaluates the surface.
struct VoxelFragment {
  ivec3 voxel{0};
  vec3 position{0.0f};  // world position of the sample
  vec3 normal{0.0f};    // interpolated vertex normal there (normal mapping happens at injection)
  uint32_t triangle = 0;
  float b1 = 0.0f, b2 = 0.0f;  // barycentrics of the sample (b0 = 1 - b1 - b2)
};

struct Voxelization {
  int n = 0;
  /// Sorted by (voxel linear index x + n*(y + n*z), triangle); at most one fragment per
  /// (triangle, voxel) for both voxelizers.
  std::vector<VoxelFragment> fragments;
  Volume occupancy;  // 1 channel, 1 where at least one fragment, else 0
  int64_t covered = 0;  // number of occupied voxels
  /// The GPU rule's MSAA sample positions (pixel units); empty for the conservative voxelizer.
  std::vector<vec2> samples;
  /// Coverage ties (freedoms/coverage_ties.h, filled by add_coverage_ties; empty until then): per
  /// fragment, 1 where a correct GL may not make it, and the fragments it may make besides these
  /// (same order as `fragments`).
  std::vector<uint8_t> may_drop;
  std::vector<VoxelFragment> may_add;
};

/// Voxel-space coordinates: (world - origin) / size * n, so voxel i covers [i, i+1).
glm::dvec3 to_voxel_space(const Scene& scene, int n, const vec3& world);

/// GL's own arithmetic in the conservative shaders (clip, depth range, in double that GLSL 4.50
/// §4.7.1 only promises to be as precise as float), in voxels: the whole bound of the gs mode,
/// part of the hardware modes' (compare/conservative_occupancy.h), and the conservative
/// voxelizer's coverage ties (freedoms/coverage_ties.h).
constexpr double kConservativeArithmetic = 1.0 / 1024.0;

/// Exact conservative voxelization; one fragment per (triangle, voxel) at the point of the
/// triangle closest to the voxel centre. With `grow` != 0 the voxel boxes are closed and grown
/// (shrunk, when negative) by that many voxels on every side: the sets a GL whose box tests are
/// that far off may make (freedoms/coverage_ties.h).
Voxelization voxelize_conservative(const Scene& scene, int n, double grow = 0.0);

/// The GPU rule with 1, 4 or 8 samples; one fragment per covered pixel (any sample), evaluated at
/// the pixel centre as GL evaluates non-centroid inputs (extrapolated barycentrics allowed).
Voxelization voxelize_gpu_rule(const Scene& scene, int n, int msaa_samples);
/// Whether the GPU rule discards alpha-masked fragments (the pass does) or keeps every covered
/// pixel (the alpha ties' candidates, freedoms/voxel_alpha_ties.h).
enum class AlphaTest { Apply, Ignore };
/// Same with the sample positions a driver reported (BackendFacts::sample_positions: pixel units,
/// lower-left origin, y up) instead of the standard pattern: 1 to 32 positions.
/// Which samples count as covered (`world`, stages/raster.h SnapWorld): the reference's own, or for
/// the judge's coverage ties (freedoms/coverage_ties.h) those every or some vertex snap covers.
Voxelization voxelize_gpu_rule(const Scene& scene, int n, const std::vector<vec2>& sample_positions,
                               AlphaTest alpha = AlphaTest::Apply, SnapWorld world = SnapWorld::Reference);

/// The window axes (u, v) of the GPU rule's orthographic projection along dominant axis `axis`, as
/// the seed's gl_Position swizzles: x-dominant (y, z), y-dominant (x, z), z-dominant (x, y).
inline void voxel_window_axes(int axis, int& u, int& v) {
  u = axis == 0 ? 1 : 0;
  v = axis == 2 ? 1 : 2;
}

/// The voxelizer settings.voxelizer selects, at settings.grid.
Voxelization voxelize(const Scene& scene, const VctSettings& settings);

/// 1 where `conservative` has a voxel and `gpu` does not (1 channel).
Volume hole_map(const Voxelization& conservative, const Voxelization& gpu);
/// The same from the two occupancy volumes.
Volume hole_map(const Volume& conservative_occupancy, const Volume& gpu_occupancy);

/// Dominant axis of a triangle as the seed's geometry shader picks it from
/// p = abs(cross(v1 - v0, v2 - v0)) in float: 2 (z) if p.z > p.x && p.z > p.y, else 0 (x) if
/// p.x > p.y, else 1 (y). Ties therefore go z < x < y in priority order as written.
int dominant_axis(const vec3& v0, const vec3& v1, const vec3& v2);

/// Exact test: does the closed triangle (voxel-space coordinates) meet the half-open box
/// [lo, lo+1)^3? Separating-axis theorem over 13 axes with open/closed interval ends.
bool triangle_overlaps_voxel(const glm::dvec3 tri[3], const glm::dvec3& lo);

/// Closed triangle against the closed box [lo, hi]: separating-axis test over the 3 box normals,
/// the triangle normal and the 9 edge cross products, in double; touching counts as meeting.
bool triangle_meets_box(const glm::dvec3 tri[3], const glm::dvec3& lo, const glm::dvec3& hi);

/// Barycentrics (b1, b2) of the point of triangle `tri` closest to `p` (Ericson, RTCD 5.1.5).
glm::dvec2 closest_point_barycentrics(const glm::dvec3 tri[3], const glm::dvec3& p);

/// x + n (y + n z): the order of Voxelization::fragments, voxel by voxel.
inline int64_t voxel_linear_index(int n, const ivec3& v) { return (int64_t(v.z) * n + v.y) * n + v.x; }
/// The total order of Voxelization::fragments: by voxel, then by triangle.
inline bool fragment_before(int n, const VoxelFragment& a, const VoxelFragment& b) {
  const int64_t la = voxel_linear_index(n, a.voxel), lb = voxel_linear_index(n, b.voxel);
  return la != lb ? la < lb : a.triangle < b.triangle;
}

/// Sorts fragments, fills occupancy and the covered count.
Voxelization finish_voxelization(int n, std::vector<VoxelFragment> fragments);

}  // namespace vct
