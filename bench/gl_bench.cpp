// GL stage times (GPU timer queries) beside the CPU reference's (wall clock) for the same scene
// and settings. The two pipelines cut stages slightly differently, so times are also summed into
// common groups (e.g. GL's voxelize + resolve + mips vs the CPU's voxelize + inject/mips), and the
// CPU/GL ratio is printed per group. Prints; never passes or fails.
// Usage: gl_bench [SCENE] [--width W] [--height H] [--grid N] [--runs K] [--threads T]
// On llvmpipe the "GPU" is the same CPU, so ratios compare two CPU implementations.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "compare/stage_timings.h"
#include "core/parallel.h"
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"

using namespace vct;

int main(int argc, char** argv) {
  std::string scene_path;
  Settings s;
  s.vct.width = s.vct.height = 128;
  s.vct.grid = 64;
  s.vct.shadow_map_size = 512;
  s.vct.msaa_samples = 4;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  int runs = 3;
  for (int i = 1; i < argc; ++i) {
    auto next = [&](const char* flag) {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "gl_bench: %s needs a value\n", flag);
        std::exit(2);
      }
      return std::atoi(argv[++i]);
    };
    if (!std::strcmp(argv[i], "--width")) s.vct.width = next("--width");
    else if (!std::strcmp(argv[i], "--height")) s.vct.height = next("--height");
    else if (!std::strcmp(argv[i], "--grid")) s.vct.grid = next("--grid");
    else if (!std::strcmp(argv[i], "--runs")) runs = std::max(1, next("--runs"));
    else if (!std::strcmp(argv[i], "--threads")) s.threads = next("--threads");
    else scene_path = argv[i];
  }
  try {
    set_thread_count(s.threads);
    const Scene scene = load_scene(scene_path);
    gl::GlContext ctx;
    std::printf("scene %s, %dx%d, grid %d^3, shadow map %d^2, MSAA %d, fixed-point reduction, %d runs (median)\n",
                scene.source.c_str(), s.vct.width, s.vct.height, s.vct.grid, s.vct.shadow_map_size, s.vct.msaa_samples,
                runs);
    std::printf("GL: %s | %s\n\n", ctx.renderer().c_str(), ctx.version().c_str());
    gl::render_gl_frame(ctx, scene, s);  // warm-up: shader compilation, driver caches
    std::vector<StageTimes> gl_runs, ref_runs;
    for (int r = 0; r < runs; ++r) gl_runs.push_back(gl::render_gl_frame(ctx, scene, s).timings_ms);
    for (int r = 0; r < runs; ++r) ref_runs.push_back(render_ref_frame(scene, s).timings_ms);
    const StageTimes gl_t = median_times(gl_runs), ref_t = median_times(ref_runs);
    std::printf("%-24s %12s %12s %10s\n", "stage group", "GL ms", "CPU ref ms", "CPU/GL");
    for (const StageGroup& g : stage_groups()) {
      const double a = sum_stages(gl_t, g.gl), b = sum_stages(ref_t, g.ref);
      if (a > 0.0)
        std::printf("%-24s %12.2f %12.2f %10.2f\n", g.name.c_str(), a, b, b / a);
      else
        std::printf("%-24s %12.2f %12.2f %10s\n", g.name.c_str(), a, b, "-");  // no GL counterpart
    }
    std::printf("\nGL stages (GPU timer queries):\n");
    for (const auto& [k, v] : gl_t) std::printf("  %-26s %10.2f ms\n", k.c_str(), v);
    std::printf("CPU reference stages (wall clock):\n");
    for (const auto& [k, v] : ref_t) std::printf("  %-26s %10.2f ms\n", k.c_str(), v);
  } catch (const EnvironmentError& e) {
    std::fprintf(stderr, "gl_bench: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gl_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
