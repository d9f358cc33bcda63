// Path tracer throughput beside raw Embree: on the built-in scene (or argv[1]) measures
//  * raw rtcIntersect1 / rtcOccluded1 rays per second for random rays (origins uniform in the
//    scene bounds, directions uniform on the sphere), no shading;
//  * the path tracer's primary rays (max_depth 0: camera ray + first-hit surface and material
//    evaluation, emission) and full paths (NEE to every light + BSDF continuation, default
//    settings), counting every ray traced (primary, secondary = BSDF, shadow);
// and prints raw / path-tracer rays-per-second ratios (the shading overhead).
// Prints; never passes or fails. Usage: pt_bench [SCENE] [--size W] [--spp N] [--threads T]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/path_tracer.h"
#include "pt/rng.h"
#include "scene/gltf_loader.h"

namespace {

using namespace vct;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Rays {
  std::vector<vec3> org, dir;
};

Rays random_rays(const Bounds3& b, size_t n) {
  Rays r;
  pt::Pcg32 rng(42u, 7u);
  for (size_t i = 0; i < n; ++i) {
    r.org.push_back(b.lo + b.extent() * vec3(rng.next_float(), rng.next_float(), rng.next_float()));
    const float z = 1.0f - 2.0f * rng.next_float(), phi = 2.0f * kPi * rng.next_float();
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    r.dir.push_back(vec3(s * std::cos(phi), s * std::sin(phi), z));
  }
  return r;
}

/// Rays per second of `fn(i)` over all rays, chunked over the workers; best of 3 runs.
template <class Fn>
double rays_per_second(size_t n, Fn fn) {
  constexpr int64_t kChunk = 4096;
  const int64_t chunks = int64_t((n + kChunk - 1) / kChunk);
  double best = 0.0;
  for (int run = 0; run < 3; ++run) {
    std::vector<int> sink(size_t(chunks), 0);
    const auto t0 = std::chrono::steady_clock::now();
    parallel_for(chunks, [&](int64_t c) {
      int hits = 0;
      for (size_t i = size_t(c * kChunk); i < std::min(n, size_t((c + 1) * kChunk)); ++i) hits += fn(i) ? 1 : 0;
      sink[size_t(c)] = hits;
    });
    best = std::max(best, double(n) / seconds_since(t0));
  }
  return best;
}

double render_rate(const Scene& scene, const PtSettings& ps, int spp, pt::RayCounts& counts, double& seconds) {
  const pt::PathTracer tracer(scene, ps);
  pt::Accumulator acc(ps.width, ps.height);
  const auto t0 = std::chrono::steady_clock::now();
  counts = tracer.render(acc, uint32_t(spp));
  seconds = seconds_since(t0);
  return double(counts.total()) / seconds;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path;
  int size = 256, spp = 8, threads = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
      size = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--spp") && i + 1 < argc)
      spp = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
      threads = std::atoi(argv[++i]);
    else
      scene_path = argv[i];
  }
  set_thread_count(threads);
  const Scene scene = load_scene(scene_path);
  std::printf("scene %s: %zu triangles, %d threads, %dx%d, %d spp\n", scene.source.c_str(), scene.triangle_count(),
              thread_count(), size, size, spp);

  const pt::EmbreeScene rt(scene);
  const size_t n = 2000000;
  const Rays rays = random_rays(scene.bounds, n);
  const double raw_hit = rays_per_second(n, [&](size_t i) {
    return rt.intersect(rays.org[i], rays.dir[i], 0.0f, std::numeric_limits<float>::infinity()).hit;
  });
  const double raw_occ = rays_per_second(n, [&](size_t i) {
    return rt.occluded(rays.org[i], rays.dir[i], 0.0f, std::numeric_limits<float>::infinity());
  });
  std::printf("raw rtcIntersect1 (random rays):  %8.2f Mrays/s\n", raw_hit * 1e-6);
  std::printf("raw rtcOccluded1  (random rays):  %8.2f Mrays/s\n", raw_occ * 1e-6);

  PtSettings ps;
  ps.width = ps.height = size;
  pt::RayCounts counts;
  double secs = 0.0;
  ps.max_depth = 0;  // camera ray + first-hit shading only
  const double primary = render_rate(scene, ps, spp, counts, secs);
  std::printf("path tracer, primary only:        %8.2f Mrays/s  (%.3f s, %llu rays)\n", primary * 1e-6, secs,
              static_cast<unsigned long long>(counts.total()));
  ps.max_depth = PtSettings{}.max_depth;
  const double full = render_rate(scene, ps, spp, counts, secs);
  std::printf("path tracer, full paths:          %8.2f Mrays/s  (%.3f s; primary %llu, secondary %llu, shadow %llu)\n",
              full * 1e-6, secs, static_cast<unsigned long long>(counts.primary),
              static_cast<unsigned long long>(counts.secondary), static_cast<unsigned long long>(counts.shadow));
  std::printf("  paths/s %.2f M, secondary (BSDF) rays/s %.2f M\n", double(counts.primary) / secs * 1e-6,
              double(counts.secondary) / secs * 1e-6);
  std::printf("ratio raw intersect / primary:    %8.2f\n", raw_hit / primary);
  std::printf("ratio raw intersect / full paths: %8.2f\n", raw_hit / full);
  return 0;
}
