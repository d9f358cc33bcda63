#include "pt/path_tracer.h"

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/parallel.h"

namespace vct::pt {

namespace {
constexpr int kTile = 16;
// The per-pixel first vertices are kept across passes up to kPtFirstVertexBudget (a 1024^2
// image); larger images trace each sample's first vertex anew. estimate_memory counts them.
static_assert(sizeof(Integrator::FirstVertex) <= kPtFirstVertexBytes, "core/memory_budget.h's size");
// Pixel samples per parallel loop: a small image runs several passes per tile in one loop, so the
// workers meet at a barrier (and spin there, libgomp's default) once per batch, not once per pass.
constexpr uint64_t kBatchSamples = uint64_t(1) << 18;

// Passes in the batch starting at pass s: the first pass of a call alone (it traces the first
// vertices, and a caller polling for a stop sees it early), then enough for kBatchSamples, at
// least 1, not past target.
uint32_t batch_passes(size_t pixels, uint32_t first_pass, uint32_t s, uint32_t target) {
  if (s == first_pass) return 1;
  const uint64_t want = std::max<uint64_t>(1, (kBatchSamples + pixels - 1) / std::max<size_t>(pixels, 1));
  return uint32_t(std::min<uint64_t>(want, target - s));
}
}  // namespace

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
  // Every sample of a pixel starts from the same first vertex (camera rays through the pixel
  // centre): it is traced and shaded in the first pass and reused by the others, with the same
  // floats (Integrator::FirstVertex). Its camera and punctual-light shadow rays are traced, and
  // counted, once per pixel.
  const size_t pixels = size_t(acc.width()) * size_t(acc.height());
  const bool keep_first = pixels * kPtFirstVertexBytes <= kPtFirstVertexBudget;
  std::vector<Integrator::FirstVertex> first(keep_first ? pixels : 0);
  const uint32_t first_pass = acc.samples();
  for (uint32_t s = acc.samples(); s < target_spp;) {
    // Passes [s, s_end) in one loop; each pixel takes its samples in order, so its sums are the
    // same floats as one pass per loop (docs/pathtracer.md "Passes in batches").
    const uint32_t s_end = s + (keep_first ? batch_passes(pixels, first_pass, s, target_spp) : 1u);
    parallel_for(tiles, [&](int64_t t) {
      const int x0 = int(t % tiles_x) * kTile, y0 = int(t / tiles_x) * kTile;
      const int x1 = std::min(x0 + kTile, acc.width()), y1 = std::min(y0 + kTile, acc.height());
      RayCounts counts;
      // The tile's samples of this batch, pixel by pixel and each pixel's in index order, go in
      // packets of kPacket lanes (Integrator::trace_packet: the same floats as one trace() each;
      // a pixel's sums still see its samples in order, docs/pathtracer.md "Packets").
      Integrator::Lane lanes[EmbreeScene::kPacket];
      PathSample samples[EmbreeScene::kPacket];
      int n = 0;
      const auto flush = [&] {
        integrator_.trace_packet(lanes, n, samples, counts);
        for (int i = 0; i < n; ++i) acc.add(lanes[i].x, lanes[i].y, lanes[i].sample, samples[i]);
        n = 0;
      };
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          if (!keep_first) {
            acc.add(x, y, s, integrator_.trace(x, y, s, counts));
            continue;
          }
          Integrator::FirstVertex& f = first[size_t(y) * size_t(acc.width()) + size_t(x)];
          if (s == first_pass) f = integrator_.first_vertex(x, y, counts);
          for (uint32_t p = s; p < s_end; ++p) {
            lanes[n++] = Integrator::Lane{&f, x, y, p};
            if (n == EmbreeScene::kPacket) flush();
          }
        }
      if (n > 0) flush();
      per_tile[size_t(t)] = counts;
    });
    s = s_end;
    acc.set_samples(s);
    for (const RayCounts& c : per_tile) total.add(c);
    if (after_pass && !after_pass(acc, total)) break;
  }
  return total;
}

}  // namespace vct::pt
