// (b) The GPU's voxelization rule, emulated: the seed's geometry shader projects each triangle
// orthographically along its dominant axis into an n x n viewport; the rasterizer covers pixels
// with the MSAA sample pattern; the fragment shader turns the interpolated position (evaluated at
// the pixel centre) into the voxel along the axis with floor(), clamped to the grid.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/parallel_gather.h"
#include "scene/alpha_mask.h"
#include "scene/surface.h"
#include "stages/raster.h"
#include "stages/voxelize.h"

namespace vct {

Voxelization voxelize_gpu_rule(const Scene& scene, int n, int msaa_samples) {
  return voxelize_gpu_rule(scene, n, standard_sample_positions(msaa_samples));
}

namespace {

// The sample test of `world` (raster.h SnapWorld).
auto sample_test(const RasterTriangle& t, SnapWorld world) {
  return [&t, world](const EdgeSetup& e, int64_t px, int64_t py) { return covered_in_world(t, e, world, px, py); };
}

}  // namespace

Voxelization voxelize_gpu_rule(const Scene& scene, int n, const std::vector<vec2>& samples, AlphaTest alpha,
                               SnapWorld world) {
  if (samples.empty() || samples.size() > 32)
    throw std::invalid_argument("voxelize_gpu_rule: 1 to 32 sample positions (one coverage bit each)");
  std::vector<VoxelFragment> fragments = parallel_gather<VoxelFragment>(
      int64_t(scene.triangles.size()), [&](int64_t ti, std::vector<VoxelFragment>& out) {
    const uvec3 t = scene.triangles[size_t(ti)];
    const vec3 w[3] = {scene.positions[t.x], scene.positions[t.y], scene.positions[t.z]};
    const int axis = dominant_axis(w[0], w[1], w[2]);
    int pu, pv;
    voxel_window_axes(axis, pu, pv);
    glm::dvec3 v[3];
    vec4 clip[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = to_voxel_space(scene, n, w[i]);
      // Volume texture coordinates [0,1] -> clip [-1,1] (w = 1, orthographic).
      clip[i] = vec4(float(v[i][pu] / n * 2.0 - 1.0), float(v[i][pv] / n * 2.0 - 1.0), 0.0f, 1.0f);
    }
    thread_local std::vector<RasterTriangle> rt;
    rt.clear();
    setup_triangle(clip, n, n, uint32_t(ti), rt);
    const bool alpha_tested = alpha == AlphaTest::Apply && triangle_alpha_tested(scene, uint32_t(ti));
    for (const RasterTriangle& r : rt) {
      // A snap moves coverage by a few subpixels at most: one pixel of margin holds it.
      const int grow = world == SnapWorld::Possible ? 1 : 0;
      rasterize_covering(r, samples, 0, n - 1, 0, n - 1, grow, sample_test(r, world), [&](const RasterFragment& f) {
        // A masked fragment adds neither opacity nor light (voxelize.frag discards it); tested at
        // the pixel centre where the fragment's attributes are evaluated.
        if (alpha_tested && surface_masked(scene, uint32_t(ti), f.bary.y, f.bary.z)) return;
        // Relative to vertex 0, as GL interpolates: a triangle lying in one plane of constant
        // depth gets exactly that depth (the absolute b0*d0+b1*d1+b2*d2 form rounds across it).
        const double depth = v[0][axis] + double(f.bary.y) * (v[1][axis] - v[0][axis]) +
                             double(f.bary.z) * (v[2][axis] - v[0][axis]);
        ivec3 voxel;
        voxel[pu] = f.x;
        voxel[pv] = f.y;
        voxel[axis] = int(std::clamp(std::floor(depth), 0.0, double(n - 1)));
        const SurfacePoint sp = interpolate_surface(scene, uint32_t(ti), f.bary.y, f.bary.z);
        out.push_back({voxel, sp.position, sp.normal, uint32_t(ti), f.bary.y, f.bary.z});
      });
    }
      });
  Voxelization vox = finish_voxelization(n, std::move(fragments));
  vox.samples = samples;
  return vox;
}

}  // namespace vct
