// How much memory a run will need, estimated up front, so a grid or image that cannot fit is
// refused with a clear message (issue 2) instead of dying in the allocator halfway through.
#pragma once

#include <cstdint>
#include <string>

#include "core/settings.h"

namespace vct {

/// Estimated peak bytes of the CPU pipelines for `s` (what the ref backend allocates; the GL
/// backend needs less host memory). Lower bounds: scene data and temporaries are not counted.
struct MemoryEstimate {
  uint64_t voxels = 0;       // base grid + reduction buffers + mip pyramids (x2 with multibounce)
  uint64_t images = 0;       // G-buffer, frame component images, shadow maps
  uint64_t path_tracer = 0;  // path tracer accumulation and AOV images
  uint64_t total() const { return voxels + images + path_tracer; }
};

MemoryEstimate estimate_memory(const Settings& s);

/// Physical memory of this machine in bytes (sysconf); 0 if unknown.
uint64_t physical_memory_bytes();

/// Throws InputError saying how much is needed when the estimate exceeds `available` bytes
/// (default: physical memory). Does nothing if `available` is 0 (unknown).
void check_memory_budget(const Settings& s, uint64_t available = physical_memory_bytes());

/// Peak resident set size of this process so far in bytes (getrusage); 0 if unknown.
uint64_t peak_rss_bytes();

/// "1.5 GiB", "300 MiB", ...
std::string format_bytes(uint64_t bytes);

}  // namespace vct
