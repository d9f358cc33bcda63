#include "pt/path_tracer.h"

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"

namespace vct::pt {

namespace {
constexpr int kTile = 16;
}

PathTracer::PathTracer(const Scene& scene, const PtSettings& settings, const ParticleOptions& particles)
    : scene_(scene),
      settings_(settings),
      rt_(scene),
      lights_(scene),
      particles_(scene, particles),
      particle_layer_(particles_.camera_layer(scene, rt_, settings.width, settings.height)),
      integrator_(scene, rt_, lights_, settings, &particles_, &particle_layer_) {}

RayCounts PathTracer::render(Accumulator& acc, uint32_t target_spp, const AfterPass& after_pass) const {
  if (acc.width() != settings_.width || acc.height() != settings_.height)
    throw InputError("", "accumulator size differs from the path tracer's image size");
  const int tiles_x = (acc.width() + kTile - 1) / kTile, tiles_y = (acc.height() + kTile - 1) / kTile;
  const int64_t tiles = int64_t(tiles_x) * tiles_y;
  RayCounts total;
  std::vector<RayCounts> per_tile(static_cast<size_t>(tiles));
  for (uint32_t s = acc.samples(); s < target_spp; ++s) {
    parallel_for(tiles, [&](int64_t t) {
      const int x0 = int(t % tiles_x) * kTile, y0 = int(t / tiles_x) * kTile;
      const int x1 = std::min(x0 + kTile, acc.width()), y1 = std::min(y0 + kTile, acc.height());
      RayCounts counts;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) acc.add(x, y, s, integrator_.trace(x, y, s, counts));
      per_tile[size_t(t)] = counts;
    });
    acc.set_samples(s + 1);
    for (const RayCounts& c : per_tile) total.add(c);
    if (after_pass && !after_pass(acc, total)) break;
  }
  return total;
}

}  // namespace vct::pt
