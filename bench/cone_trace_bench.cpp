// CPU cone tracing, the frame's fast path (ConeFrame + MipSampler, stages/mip_sampler.h) against
// the readable one (the free functions on voxel_sampler.h, per-pixel set-up, as the reference
// traced before issue 16), on one scene's own G-buffer and mips: best-of-R CPU milliseconds of the
// indirect pass (diffuse + specular cones) and of the cone soft shadows, and their ratio. Also
// checks that both paths give the same bits. Prints; never passes or fails.
// Usage: cone_trace_bench [SCENE] [--size W] [--grid N] [--aniso] [--repeat R] [--threads T]
//        [--no-diffuse] [--no-specular] [--frame-path-only]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "core/parallel.h"
#include "scene/gltf_loader.h"
#include "stages/cone_sets.h"
#include "stages/indirect_pass.h"
#include "freedoms/reference_frame.h"
#include "stages/soft_shadow.h"

namespace {

using namespace vct;

double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

// Best of `repeat` by process CPU time (on a shared machine CPU time is steadier than wall time).
template <class F>
double best_cpu_ms(int repeat, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = cpu_ms();
    f();
    best = std::min(best, cpu_ms() - t0);
  }
  return best;
}

// The pre-issue-16 per-pixel loop: every pixel re-derives the cone block and march parameters
// and samples through voxel_sampler.h.
IndirectImages readable_indirect(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const VctSettings& s) {
  const int w = g.coverage.width, h = g.coverage.height;
  IndirectImages out;
  out.diffuse = Image(w, h, 3);
  out.specular = Image(w, h, 3);
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      const vec3 p = g.position.rgb(x, y), n = g.normal.rgb(x, y);
      if (s.diffuse_cones)
        out.diffuse.set_rgb(x, y, trace_diffuse_cones(mips, scene.volume, s, p, n, diffuse_rotation_for_pixel(s, x, y)).radiance);
      if (s.specular_cones)
        out.specular.set_rgb(
            x, y, vec3(trace_specular_cone(mips, scene.volume, s, p, n, view_vector(scene, p), g.material.at(x, y, 1))));
    }
  });
  return out;
}

Image readable_shadows(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const VctSettings& s) {
  Image vis(g.coverage.width, g.coverage.height, 1);
  parallel_rows(g.coverage.height, [&](int y) {
    for (int x = 0; x < g.coverage.width; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      float sum = 0.0f;
      for (const Light& l : scene.lights) sum += trace_shadow_cone(mips, scene.volume, s, g.position.rgb(x, y), l);
      vis.at(x, y, 0) = sum;
    }
  });
  return vis;
}

bool same_bits(const Image& a, const Image& b) {
  return a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path;
  Settings s;
  s.vct.width = s.vct.height = 512;
  s.vct.grid = 128;
  int repeat = 3;
  bool frame_only = false;  // for profiling the frame path alone
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) s.vct.width = s.vct.height = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--grid") && i + 1 < argc) s.vct.grid = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) set_thread_count(std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--aniso")) s.vct.anisotropic = true;
    else if (!std::strcmp(argv[i], "--no-diffuse")) s.vct.diffuse_cones = false;
    else if (!std::strcmp(argv[i], "--no-specular")) s.vct.specular_cones = false;
    else if (!std::strcmp(argv[i], "--frame-path-only")) frame_only = true;
    else scene_path = argv[i];
  }
  const Scene scene = load_scene(scene_path);
  const FrameResult f = render_ref_frame(scene, s);
  const GBuffer& g = f.gbuffer;
  std::printf("scene %s, %dx%d, grid %d^3, %s, %d threads, best of %d by process CPU time\n", scene.source.c_str(),
              s.vct.width, s.vct.height, s.vct.grid, s.vct.anisotropic ? "anisotropic" : "isotropic", thread_count(), repeat);
  IndirectImages fast, slow;
  const double slow_ms = frame_only ? 0.0 : best_cpu_ms(repeat, [&] { slow = readable_indirect(scene, g, f.mips, s.vct); });
  const double fast_ms = best_cpu_ms(repeat, [&] { fast = trace_indirect(scene, g, f.mips, s.vct); });
  std::printf("indirect cones: readable %9.1f ms   frame path %9.1f ms   speed-up %.2fx   same bits: %s\n", slow_ms, fast_ms,
              slow_ms / fast_ms, same_bits(fast.diffuse, slow.diffuse) && same_bits(fast.specular, slow.specular) ? "yes" : "NO");
  Image vis_slow, vis_fast;
  const double shadow_slow =
      frame_only ? 0.0 : best_cpu_ms(repeat, [&] { vis_slow = readable_shadows(scene, g, f.mips, s.vct); });
  const double shadow_fast = best_cpu_ms(repeat, [&] { shade_direct_soft(scene, g, f.mips, s.vct, &vis_fast); });
  std::printf("soft shadows:   readable %9.1f ms   frame path %9.1f ms   speed-up %.2fx   (includes shading)\n", shadow_slow,
              shadow_fast, shadow_slow / shadow_fast);
  return 0;
}
