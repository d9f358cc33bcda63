#include "freedoms/snap_window.h"

#include <algorithm>
#include <cmath>

#include "stages/raster.h"
#include "stages/voxelize.h"

namespace vct {

bool snap_window(const Scene& scene, int n, const VoxelFragment& f, SnapWindow& w) {
  const uvec3 t = scene.triangles[f.triangle];
  const vec3 p[3] = {scene.positions[t.x], scene.positions[t.y], scene.positions[t.z]};
  const int axis = dominant_axis(p[0], p[1], p[2]);
  const int pu = axis == 0 ? 1 : 0, pv = axis == 2 ? 1 : 2;  // as voxelize_gpu.cpp's window axes
  glm::dvec3 v[3];
  for (int i = 0; i < 3; ++i) v[i] = to_voxel_space(scene, n, p[i]);
  w.axis = axis;
  w.depth0 = v[0][axis], w.depth_e1 = v[1][axis] - v[0][axis], w.depth_e2 = v[2][axis] - v[0][axis];
  w.a = v[1][pu] - v[0][pu], w.b = v[2][pu] - v[0][pu];
  w.c = v[1][pv] - v[0][pv], w.d = v[2][pv] - v[0][pv];
  w.det = w.a * w.d - w.b * w.c;
  if (std::abs(w.det) < 1e-300) return false;
  w.w0 = p[0], w.e1 = glm::dvec3(p[1]) - w.w0, w.e2 = glm::dvec3(p[2]) - w.w0;
  const double g = (std::abs(w.a) + std::abs(w.b) + std::abs(w.c) + std::abs(w.d) + std::abs(w.d - w.c) +
                    std::abs(w.a - w.b)) / std::abs(w.det);
  const double sum_l = std::abs(1.0 - double(f.b1) - double(f.b2)) + std::abs(double(f.b1)) + std::abs(double(f.b2));
  const double sg = kVertexSnapStep * g;
  w.bounded = sg < 0.5;
  w.reach = kVertexSnapStep * sum_l / (1.0 - std::min(sg, 0.5));
  return true;
}

VoxelFragment shifted_fragment(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, double du, double dv,
                               SurfacePoint* point) {
  const double db1 = (w.d * du - w.b * dv) / w.det, db2 = (-w.c * du + w.a * dv) / w.det;
  VoxelFragment out = f;
  out.b1 = float(double(f.b1) + db1);
  out.b2 = float(double(f.b2) + db2);
  const SurfacePoint sp = interpolate_surface(scene, f.triangle, out.b1, out.b2);
  out.position = sp.position;
  out.normal = sp.normal;
  if (point) *point = sp;
  return out;
}

SurfacePoint surface_at(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, double du, double dv) {
  SurfacePoint sp;
  shifted_fragment(scene, w, f, du, dv, &sp);
  return sp;
}

}  // namespace vct
