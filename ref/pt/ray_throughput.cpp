#include "pt/ray_throughput.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <vector>

#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/embree_scene.h"
#include "pt/path_tracer.h"
#include "pt/rng.h"

namespace vct::pt {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

struct Rate {
  double wall = 0.0, cpu = 0.0;  // per second of each, best of the runs
};

struct Rays {
  std::vector<vec3> org, dir;
};

Rays random_rays(const Bounds3& b, size_t n) {
  Rays r;
  r.org.reserve(n);
  r.dir.reserve(n);
  Pcg32 rng(42u, 7u);
  for (size_t i = 0; i < n; ++i) {
    r.org.push_back(b.lo + b.extent() * vec3(rng.next_float(), rng.next_float(), rng.next_float()));
    const float z = 1.0f - 2.0f * rng.next_float(), phi = 2.0f * kPi * rng.next_float();
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    r.dir.push_back(vec3(s * std::cos(phi), s * std::sin(phi), z));
  }
  return r;
}

/// Rays per second of `fn(i)` over all rays, in chunks of 4096 over the workers; best of 3 runs
/// (the machine is shared, the best run is the least disturbed one).
template <class Fn>
Rate rays_per_second(size_t n, Fn fn) {
  constexpr int64_t kChunk = 4096;
  const int64_t chunks = int64_t((n + kChunk - 1) / kChunk);
  Rate best;
  for (int run = 0; run < 3; ++run) {
    std::vector<int> sink(size_t(chunks), 0);  // keeps the queries from being optimized away
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    parallel_for(chunks, [&](int64_t c) {
      int hits = 0;
      for (size_t i = size_t(c * kChunk); i < std::min(n, size_t((c + 1) * kChunk)); ++i) hits += fn(i) ? 1 : 0;
      sink[size_t(c)] = hits;
    });
    best.cpu = std::max(best.cpu, double(n) / (process_cpu_seconds() - c0));
    best.wall = std::max(best.wall, double(n) / seconds_since(t0));
  }
  return best;
}

}  // namespace

RawRayRates measure_raw_embree(const Scene& scene, size_t n) {
  const EmbreeScene rt(scene);
  const Rays rays = random_rays(scene.bounds, n);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  RawRayRates r;
  r.rays = n;
  const Rate hit = rays_per_second(n, [&](size_t i) { return rt.intersect(rays.org[i], rays.dir[i], 0.0f, kInf).hit; });
  const Rate occ = rays_per_second(n, [&](size_t i) { return rt.occluded(rays.org[i], rays.dir[i], 0.0f, kInf); });
  r.intersect = hit.wall, r.intersect_cpu = hit.cpu;
  r.occluded = occ.wall, r.occluded_cpu = occ.cpu;
  return r;
}

TracerRate measure_path_tracer(const Scene& scene, const PtSettings& ps, int spp) {
  const PathTracer tracer(scene, ps);
  TracerRate r;
  // Best of 3, as for the raw rates above, so both sides of the ratio see the same treatment.
  for (int run = 0; run < 3; ++run) {
    Accumulator acc(ps.width, ps.height);
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    const RayCounts counts = tracer.render(acc, uint32_t(spp));
    const double cpu = process_cpu_seconds() - c0;
    const double seconds = seconds_since(t0);
    if (run == 0 || seconds < r.seconds) {
      r.counts = counts;
      r.seconds = seconds;
    }
    if (run == 0 || cpu < r.cpu_seconds) r.cpu_seconds = cpu;
  }
  r.rays_per_second = r.seconds > 0.0 ? double(r.counts.total()) / r.seconds : 0.0;
  r.rays_per_cpu_second = r.cpu_seconds > 0.0 ? double(r.counts.total()) / r.cpu_seconds : 0.0;
  return r;
}

}  // namespace vct::pt
