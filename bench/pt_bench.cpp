// Path tracer throughput beside raw Embree: on the built-in scene (or argv[1]) measures
//  * raw rtcIntersect1 / rtcOccluded1 rays per second for random rays (origins uniform in the
//    scene bounds, directions uniform on the sphere), no shading;
//  * the path tracer's primary rays (max_depth 0, one pass: camera ray + first-hit surface and
//    material evaluation, emission) and full paths (NEE to every light + BSDF continuation, default
//    settings), counting every ray traced (primary, secondary = BSDF, shadow);
// and prints raw / path-tracer rays-per-second ratios (the shading overhead).
// Prints; never passes or fails. Usage: pt_bench [SCENE] [--size W] [--spp N] [--threads T]
//                                             [--sampler sobol|independent]
#include <cstdio>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "core/parallel.h"
#include "pt/ray_throughput.h"
#include "scene/gltf_loader.h"

using namespace vct;

int main(int argc, char** argv) {
  std::string scene_path, sampler_name = to_string(PtSettings{}.sampler);
  int size = 256, spp = 8, threads = 0;
  CLI::App app{"Path tracer throughput beside raw Embree: prints rays per second and their ratios; never passes or fails"};
  app.add_option("scene", scene_path, "glTF scene (default: the built-in Cornell box)");
  app.add_option("--size", size, "Image width and height")->check(CLI::Range(1, 8192));
  app.add_option("--spp", spp, "Samples per pixel of the full-path measurement")->check(CLI::Range(1, 1 << 20));
  app.add_option("--threads", threads, "Threads (0 = all cores)")->check(CLI::Range(0, 1024));
  app.add_option("--sampler", sampler_name, "sobol | independent")->check(CLI::IsMember({"sobol", "independent"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {  // --help exits 0; a usage error 2, as every vct command
    return app.exit(e) == 0 ? 0 : 2;
  }
  const PtSampler sampler = sampler_name == "independent" ? PtSampler::Independent : PtSampler::Sobol;
  set_thread_count(threads);
  Scene scene;
  try {
    scene = load_scene(scene_path);
  } catch (const std::exception& e) {  // one line, exit 2, as every vct command (README)
    std::fprintf(stderr, "pt_bench: %s\n", e.what());
    return 2;
  }
  std::printf("scene %s: %zu triangles, %d threads, %dx%d, %d spp, sampler %s\n", scene.source.c_str(),
              scene.triangle_count(), thread_count(), size, size, spp, to_string(sampler).c_str());

  const pt::RawRayRates raw = pt::measure_raw_embree(scene);
  const double raw_hit = raw.intersect, raw_occ = raw.occluded;
  std::printf("raw rtcIntersect1 (random rays):  %8.2f Mrays/s\n", raw_hit * 1e-6);
  std::printf("raw rtcOccluded1  (random rays):  %8.2f Mrays/s\n", raw_occ * 1e-6);

  PtSettings ps;
  ps.width = ps.height = size;
  ps.sampler = sampler;
  ps.max_depth = 0;  // camera ray + first-hit shading only
  // One pass: later passes reuse each pixel's first vertex (Integrator::FirstVertex) and trace
  // nothing at max_depth 0.
  pt::TracerRate rate = pt::measure_path_tracer(scene, ps, 1);
  pt::RayCounts counts = rate.counts;
  double secs = rate.seconds;
  const double primary = rate.rays_per_second;
  std::printf("path tracer, primary only:        %8.2f Mrays/s  (%.3f s, %llu rays)\n", primary * 1e-6, secs,
              static_cast<unsigned long long>(counts.total()));
  ps.max_depth = PtSettings{}.max_depth;
  rate = pt::measure_path_tracer(scene, ps, spp);
  counts = rate.counts;
  secs = rate.seconds;
  const double full = rate.rays_per_second;
  std::printf("path tracer, full paths:          %8.2f Mrays/s  (%.3f s; primary %llu, secondary %llu, shadow %llu)\n",
              full * 1e-6, secs, static_cast<unsigned long long>(counts.primary),
              static_cast<unsigned long long>(counts.secondary), static_cast<unsigned long long>(counts.shadow));
  // counts.primary is one camera ray per pixel (the first vertex is traced once, in pass 1).
  const double paths = double(size) * double(size) * double(spp);
  std::printf("  paths/s %.2f M, rays per path %.2f, secondary (BSDF) rays/s %.2f M\n", paths / secs * 1e-6,
              double(counts.total()) / paths, double(counts.secondary) / secs * 1e-6);
  std::printf("ratio raw intersect / primary:    %8.2f\n", raw_hit / primary);
  std::printf("ratio raw intersect / full paths: %8.2f\n", raw_hit / full);
  // The same by process CPU time (steadier on a shared machine): full paths as a share of raw.
  std::printf("by CPU time: raw intersect %.2f Mrays/s, occluded %.2f; full paths %.2f Mrays/s = %.0f %% of raw intersect\n",
              raw.intersect_cpu * 1e-6, raw.occluded_cpu * 1e-6, rate.rays_per_cpu_second * 1e-6,
              100.0 * rate.rays_per_cpu_second / raw.intersect_cpu);
  return 0;
}
