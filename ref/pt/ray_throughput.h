// Path tracer throughput beside raw Embree on the same scene (used by `vct bench` and pt_bench):
//  * raw rtcIntersect1 / rtcOccluded1 rays per second for random rays (origins uniform in the
//    scene bounds, directions uniform on the sphere), no shading: Embree's ceiling on this scene;
//  * the path tracer's primary rays (max_depth 0) and full paths (default depth), counting every
//    ray traced (primary, BSDF, shadow).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/settings.h"
#include "pt/integrator.h"
#include "scene/scene.h"

namespace vct::pt {

struct RawRayRates {
  double intersect = 0.0, occluded = 0.0;  // rays per second (best of 3 runs)
  // The same per second of process CPU time (best of 3): steadier than wall time on a shared
  // machine, where other jobs take turns on the cores.
  double intersect_cpu = 0.0, occluded_cpu = 0.0;
  size_t rays = 0;
};

/// Raw Embree throughput for `rays` random rays over the workers (parallel_for).
RawRayRates measure_raw_embree(const Scene& scene, size_t rays = 2000000);

struct TracerRate {
  double rays_per_second = 0.0, seconds = 0.0;
  double rays_per_cpu_second = 0.0, cpu_seconds = 0.0;  // process CPU time, best of 3
  RayCounts counts;
};

/// Renders `spp` passes of `ps` from scratch, 3 times, and keeps the fastest (the BVH build is
/// not timed).
TracerRate measure_path_tracer(const Scene& scene, const PtSettings& ps, int spp);

}  // namespace vct::pt
