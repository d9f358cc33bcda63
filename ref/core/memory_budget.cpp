#include "core/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

#include "core/error.h"

namespace vct {

MemoryEstimate estimate_memory(const Settings& s) {
  const VctSettings& v = s.vct;
  const uint64_t n3 = uint64_t(v.grid) * uint64_t(v.grid) * uint64_t(v.grid);
  MemoryEstimate e;
  // Base level: RGBA float + fragment count (20 B) and one RGBA accumulation buffer of doubles
  // or fixed-point sums (32 B); the CAS model keeps two more RGBA float bounds (32 B).
  uint64_t per_voxel = 20 + 32 + (v.reduction == Reduction::CasRgba8 ? 32 : 0);
  // Isotropic mips: RGBA float, levels 1.. sum to N^3/7. Anisotropic: six directional
  // pyramids starting at level 1, each N^3/7.
  uint64_t mips = 16 * n3 / 7 + (v.anisotropic ? 6 * 16 * n3 / 7 : 0);
  // Multibounce traces frame n-1's mips while building frame n's.
  if (v.bounces > 1) mips *= 2;
  e.voxels = per_voxel * n3 + mips;
  // G-buffer 21 floats + frame components 25 floats per pixel; one float shadow map per light
  // (counted once: the estimate does not know the scene).
  const uint64_t pixels = uint64_t(v.width) * uint64_t(v.height);
  e.images = pixels * 46 * 4 + uint64_t(v.shadow_map_size) * uint64_t(v.shadow_map_size) * 4;
  // Path tracer: 16 double accumulators (mean and variance of the AOVs) per pixel.
  e.path_tracer = uint64_t(s.pt.width) * uint64_t(s.pt.height) * 16 * 8;
  return e;
}

uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
}

uint64_t peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return uint64_t(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

std::string format_bytes(uint64_t bytes) {
  char buf[64];
  const double b = double(bytes);
  if (b >= 1024.0 * 1024.0 * 1024.0) std::snprintf(buf, sizeof buf, "%.1f GiB", b / (1024.0 * 1024.0 * 1024.0));
  else if (b >= 1024.0 * 1024.0) std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024.0 * 1024.0));
  else std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
  return buf;
}

void check_memory_budget(const Settings& s, uint64_t available) {
  if (available == 0) return;
  const MemoryEstimate e = estimate_memory(s);
  if (e.total() <= available) return;
  const VctSettings& v = s.vct;
  throw InputError("", "settings need about " + format_bytes(e.total()) + " (grid " + std::to_string(v.grid) + "^3" +
                           (v.anisotropic ? " anisotropic" : "") + ": " + format_bytes(e.voxels) + "; images " +
                           std::to_string(v.width) + "x" + std::to_string(v.height) + " and shadow map " +
                           std::to_string(v.shadow_map_size) + "^2: " + format_bytes(e.images) + "; path tracer " +
                           std::to_string(s.pt.width) + "x" + std::to_string(s.pt.height) + ": " +
                           format_bytes(e.path_tracer) + "), but this machine has " + format_bytes(available) +
                           " of memory; use a smaller --grid or image size");
}

}  // namespace vct
