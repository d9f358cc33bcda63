// Shadow-map rasterization on the CPU: the depth-only path (stages/depth_raster.h, what
// render_shadow_maps uses) against the visibility buffer it replaced, on the built-in Cornell
// box's spot light, with the triangle set-up + binning share and the number of covered centres.
// Prints a table (and whether the two depth buffers are equal); never passes or fails.
// Usage: shadow_map_bench [--size S] [--repeat K] [--threads 1,2]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_timing.h"
#include "core/parallel.h"
#include "io/run_dir.h"
#include "scene/gltf_loader.h"
#include "stages/depth_raster.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"

using namespace vct;
using vct::bench::best_ms;

namespace {

// Covered pixel centres summed over all triangles (fragments before the depth test).
int64_t fragment_count(const BinnedTriangles& b, int height) {
  int64_t n = 0;
  for (size_t band = 0; band < b.bands.size(); ++band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(height, y0 + kRasterBandRows) - 1;
    for (uint32_t ti : b.bands[band]) {
      const RasterTriangle& t = b.triangles[ti];
      const EdgeSetup e = edge_setup(t);
      for (int y = std::max(y0, t.ymin); y <= std::min(y1, t.ymax); ++y) {
        int x0 = t.xmin, x1 = t.xmax;
        if (centre_row_span(e, y, x0, x1)) n += x1 - x0 + 1;
      }
    }
  }
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  int size = 2048, repeat = 5;
  std::vector<int> threads = {1, 2};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) size = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads.clear();
      for (char* t = std::strtok(argv[++i], ","); t; t = std::strtok(nullptr, ",")) threads.push_back(std::atoi(t));
    }
  }
  const Scene scene = load_scene("");
  if (scene.lights.empty()) {
    std::printf("the built-in scene has no spot light\n");
    return 0;
  }
  const mat4 vp = spot_light_view_proj(scene.lights[0], scene.bounds);
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, vp, size, size);
  std::printf("scene %s: %zu triangles (%zu after clipping), shadow map %d^2, %lld covered centres (%.2f per texel), "
              "best of %d\n",
              scene.source.c_str(), scene.triangle_count(), binned.triangles.size(), size,
              static_cast<long long>(fragment_count(binned, size)),
              double(fragment_count(binned, size)) / (double(size) * double(size)), repeat);
  const bool same = render_depth(scene.positions, scene.triangles, vp, size, size) ==
                    render_visibility(scene.positions, scene.triangles, vp, size, size).depth;
  std::printf("depth-only result equals the visibility buffer's depth: %s\n", same ? "yes" : "NO");
  std::printf("\n%8s %14s %16s %18s %10s\n", "threads", "set-up+bin ms", "depth-only ms", "visibility buf ms",
              "vis/depth");
  for (int t : threads) {
    set_thread_count(t);
    const double setup = best_ms(repeat, [&] { setup_and_bin(scene.positions, scene.triangles, vp, size, size); });
    const double depth = best_ms(repeat, [&] { render_depth(scene.positions, scene.triangles, vp, size, size); });
    const double vis = best_ms(repeat, [&] { render_visibility(scene.positions, scene.triangles, vp, size, size); });
    std::printf("%8d %14.2f %16.2f %18.2f %10.2f\n", thread_count(), setup, depth, vis, vis / depth);
  }
  return 0;
}
