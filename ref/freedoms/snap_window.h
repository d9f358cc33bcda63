// A voxel fragment under the voxel raster's 2^-8 snap (docs/compare.md, "Voxel shading slack"):
// where in its triangle a correct GL may interpolate it, as a square of window offsets, and the
// fragment or surface point at an offset. Shared by the shading slack (fragment_slack.cpp) and
// the exact voxels (fragment_exactness.cpp).
#pragma once

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/raster.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// A fragment's triangle in its dominant-axis window (voxel units) and how far the snap may move
/// the fragment there. GL interpolates at the pixel centre c with the barycentrics l' of c in the
/// *snapped* triangle, so the attributes are those of the original triangle's point
/// c - sum l'_i d_i, d_i each vertex's snap (at most s per axis). Inside the triangle sum |l'_i| = 1;
/// a fragment made by a covered MSAA sample with its centre outside is extrapolated, l' reaching
/// far past [0, 1] on triangles smaller than a voxel (scanned_statue: l = (-1.38, 0.45, 1.93), GL's
/// point 1.3 s from the reference's). With l' = l(c - e) and e that shift, per axis
/// |e| <= s (sum |l_i| + G |e|), G = sum over i of |dl_i/du| + |dl_i/dv|, so
/// |e| <= s sum |l_i| / (1 - s G) where s G < 1 (docs/compare.md, "Voxel shading slack").
struct SnapWindow {
  glm::dvec3 w0, e1, e2;     // world vertex 0 and edges
  double a, b, c, d, det;    // the projected edges (P1 - P0, P2 - P0) along the window's u and v
  double reach = kVertexSnapStep;  // |e| per window axis, voxels
  bool bounded = true;             // false where s G >= 1/2 (a sliver): no bound on the shift
  int axis = 0;                    // the dominant axis (the window's depth)
  double depth0 = 0.0, depth_e1 = 0.0, depth_e2 = 0.0;  // voxel-space depth of vertex 0 and the edges'
};

/// The window of fragment f at grid n; false where the triangle's projection is degenerate.
bool snap_window(const Scene& scene, int n, const VoxelFragment& f, SnapWindow& w);

/// The fragment moved by (du, dv) voxels in its window: barycentrics are affine in window
/// coordinates, so the shift solves [P1 - P0, P2 - P0] (db1, db2) = (du, dv). `point`, where
/// given, receives the surface point it was interpolated from (surface_at's).
VoxelFragment shifted_fragment(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, double du, double dv,
                               SurfacePoint* point = nullptr);

/// The surface point of the fragment moved by (du, dv): interpolate_surface at its barycentrics.
SurfacePoint surface_at(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, double du, double dv);

}  // namespace vct
