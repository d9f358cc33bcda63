// (a) Exact conservative voxelization: every voxel whose half-open box contains a point of the
// triangle, found by the separating-axis test over the triangle's voxel bounding box.
#include <algorithm>
#include <cmath>

#include "core/parallel_gather.h"
#include "scene/alpha_mask.h"
#include "scene/surface.h"
#include "stages/voxelize.h"

namespace vct {

Voxelization voxelize_conservative(const Scene& scene, int n, double grow) {
  std::vector<VoxelFragment> fragments = parallel_gather<VoxelFragment>(
      int64_t(scene.triangles.size()), [&](int64_t ti, std::vector<VoxelFragment>& out) {
    const uvec3 t = scene.triangles[size_t(ti)];
    const glm::dvec3 v[3] = {to_voxel_space(scene, n, scene.positions[t.x]), to_voxel_space(scene, n, scene.positions[t.y]),
                             to_voxel_space(scene, n, scene.positions[t.z])};
    const glm::dvec3 lo = glm::min(v[0], glm::min(v[1], v[2])) - std::max(grow, 0.0),
                     hi = glm::max(v[0], glm::max(v[1], v[2])) + std::max(grow, 0.0);
    ivec3 a, b;
    for (int c = 0; c < 3; ++c) {
      a[c] = int(std::clamp(std::floor(lo[c]), 0.0, double(n - 1)));
      b[c] = int(std::clamp(std::floor(hi[c]), 0.0, double(n - 1)));
    }
    const bool alpha_tested = triangle_alpha_tested(scene, uint32_t(ti));
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) {
          const glm::dvec3 corner(x, y, z);
          const bool meets = grow == 0.0 ? triangle_overlaps_voxel(v, corner)
                                         : triangle_meets_box(v, corner - grow, corner + 1.0 + grow);
          if (!meets) continue;
          const glm::dvec2 bc = closest_point_barycentrics(v, corner + glm::dvec3(0.5));
          // Alpha masks are tested at the fragment's one evaluation point, as the GPU rule tests
          // its pixel centre: a voxel whose closest point is cut away holds none of this triangle
          // (docs/pipeline.md, "Voxelization").
          if (alpha_tested && surface_masked(scene, uint32_t(ti), float(bc.x), float(bc.y)))
            continue;
          const SurfacePoint sp = interpolate_surface(scene, uint32_t(ti), float(bc.x), float(bc.y));
          out.push_back({ivec3(x, y, z), sp.position, sp.normal, uint32_t(ti), float(bc.x), float(bc.y)});
        }
      });
  return finish_voxelization(n, std::move(fragments));
}

}  // namespace vct
