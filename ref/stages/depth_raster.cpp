#include "stages/depth_raster.h"

#include <algorithm>

#include "core/parallel.h"
#include "scene/alpha_mask.h"
#include "stages/raster.h"

namespace vct {

namespace {

// Depth test of the covered centres x0..x1 of row y against `row` (window x indexed).
// Edge values are carried in doubles as e(x0) + k * step (SpanEdges, stages/raster.h: exact, and
// the loop vectorizes).
void depth_test_span(const RasterTriangle& t, const EdgeSetup& e, int y, int x0, int x1, float* row) {
  const SpanEdges span(e, y, x0);
  const double* e0 = span.e0;
  const double* step = span.step;
  const double area = double(t.area2);
  float* out = row + x0;
  const int n = x1 - x0 + 1;
  for (int k = 0; k < n; ++k) {
    const double dk = double(k);
    const float d = interpolate_window_depth((e0[0] + dk * step[0]) / area,
                                             (e0[1] + dk * step[1]) / area,
                                             (e0[2] + dk * step[2]) / area, t.z);
    out[k] = d < out[k] ? d : out[k];  // GL_LESS; the min of all fragments, in any order
  }
}

// The span of an alpha-tested triangle, pixel by pixel: interpolate_at_centre gives the same depth
// bits as depth_test_span (the same exact edge values over the same area, then
// interpolate_window_depth) and the perspective-correct barycentrics the alpha test needs.
void masked_depth_span(const RasterTriangle& t, const EdgeSetup& e, int y, int x0, int x1,
                       float* row, const Scene& scene) {
  RasterFragment f;
  for (int x = x0; x <= x1; ++x) {
    interpolate_at_centre(t, e, x, y, f);
    if (!(f.depth < row[x])) continue;                                  // GL_LESS
    if (surface_masked(scene, t.source, f.bary.y, f.bary.z)) continue;  // discarded
    row[x] = f.depth;
  }
}

void depth_triangle(const RasterTriangle& t, int y0, int y1, int height, float* depth, int width,
                    const Scene* alpha_scene) {
  const EdgeSetup e = edge_setup(t);
  const bool masked = alpha_scene && triangle_alpha_tested(*alpha_scene, t.source);
  for (int y = std::max(y0, t.ymin); y <= std::min(y1, t.ymax); ++y) {
    int x0 = t.xmin, x1 = t.xmax;
    if (!centre_row_span(e, y, x0, x1)) continue;
    float* row = depth + size_t(height - 1 - y) * size_t(width);
    if (masked)
      masked_depth_span(t, e, y, x0, x1, row, *alpha_scene);
    else
      depth_test_span(t, e, y, x0, x1, row);
  }
}

}  // namespace

std::vector<float> render_depth(const std::vector<vec3>& positions,
                                const std::vector<uvec3>& triangles, const mat4& view_proj,
                                int width, int height, const Scene* alpha_scene) {
  const BinnedTriangles binned = setup_and_bin(positions, triangles, view_proj, width, height);
  std::vector<float> depth(size_t(width) * size_t(height), 1.0f);
  parallel_for(int64_t(binned.bands.size()), [&](int64_t band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(height, y0 + kRasterBandRows) - 1;
    for (uint32_t ti : binned.bands[size_t(band)])
      depth_triangle(binned.triangles[ti], y0, y1, height, depth.data(), width, alpha_scene);
  });
  return depth;
}

}  // namespace vct
