#include "freedoms/voxel_alpha_ties.h"

#include <cmath>

#include "freedoms/alpha_ties.h"
#include "freedoms/fragment_slack.h"
#include "scene/alpha_mask.h"

namespace vct {

namespace {

// (b1, b2) per pixel of triangle `t`'s orthographic projection along its dominant axis (voxel
// units are pixels: the viewport is n x n over n voxels): the inverse of the 2x2 edge matrix.
void barycentric_gradients(const Scene& scene, int n, uint32_t t, glm::dvec2& db_dx, glm::dvec2& db_dy) {
  const uvec3 tri = scene.triangles[t];
  const vec3 w[3] = {scene.positions[tri.x], scene.positions[tri.y], scene.positions[tri.z]};
  int u, v;
  voxel_window_axes(dominant_axis(w[0], w[1], w[2]), u, v);
  glm::dvec2 p[3];
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 q = to_voxel_space(scene, n, w[i]);
    p[i] = {q[u], q[v]};
  }
  const glm::dvec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const double det = e1.x * e2.y - e2.x * e1.y;
  if (det == 0.0) {
    db_dx = db_dy = glm::dvec2(0.0);
    return;
  }
  // (x, y) - p0 = b1 e1 + b2 e2, so (b1, b2) = M^-1 ((x, y) - p0), M = [e1 e2].
  db_dx = glm::dvec2(e2.y, -e1.y) / det;
  db_dy = glm::dvec2(-e2.x, e1.x) / det;
}

bool may_flip(const Scene& scene, int n, const VoxelFragment& f) {
  if (!triangle_alpha_tested(scene, f.triangle)) return false;
  // A sliver's snapped barycentrics have no bound (freedoms/fragment_slack.h voxel_snap_reach):
  // any texel, any alpha (medium seed 2). Elsewhere the snap reaches that far, more than 2^-8
  // where the fragment is extrapolated.
  const double reach = voxel_snap_reach(scene, n, f);
  if (std::isinf(reach)) return true;
  glm::dvec2 dx, dy;
  barycentric_gradients(scene, n, f.triangle, dx, dy);
  return alpha_test_may_flip_affine(scene, f.triangle, vec3(1.0f - f.b1 - f.b2, f.b1, f.b2), reach, dx, dy);
}

}  // namespace

void add_voxel_alpha_ties(const Scene& scene, const Voxelization& vox, std::vector<uint8_t>& may_drop,
                          std::vector<VoxelFragment>& may_add) {
  if (vox.samples.empty() || !scene_has_alpha_test(scene)) return;
  // Every pixel some snap covers, masks ignored: a superset of vox.fragments in the same (voxel,
  // triangle) order, so one walk pairs each kept fragment with its entry.
  const Voxelization all = voxelize_gpu_rule(scene, vox.n, vox.samples, AlphaTest::Ignore, SnapWorld::Possible);
  size_t k = 0;
  for (const VoxelFragment& f : all.fragments) {
    while (k < vox.fragments.size() && fragment_before(vox.n, vox.fragments[k], f)) ++k;
    const bool kept = k < vox.fragments.size() && vox.fragments[k].voxel == f.voxel &&
                      vox.fragments[k].triangle == f.triangle;
    if (!may_flip(scene, vox.n, f)) continue;
    if (kept)
      may_drop[k] = 1;
    else
      may_add.push_back(f);
  }
}

}  // namespace vct
