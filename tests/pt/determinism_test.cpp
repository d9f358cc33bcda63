// The path tracer's sums are byte-identical for any thread count, and rendering in several
// calls (passes appended later) gives the same bytes as one call: the basis of resumable renders.
// Reusing a pixel's first vertex across its samples (Integrator::FirstVertex) gives the same bytes
// as tracing each sample from the camera.
#include <gtest/gtest.h>

#include <cstring>

#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/embree_scene.h"
#include "pt/emissive_lights.h"
#include "pt/integrator.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

PtSettings small_settings() {
  PtSettings ps;
  ps.width = 20;  // not a multiple of the 16-pixel tile: edge tiles too
  ps.height = 18;
  ps.max_depth = 6;
  ps.rr_start_depth = 2;
  ps.seed = 3;
  return ps;
}

Accumulator render_with_threads(const Scene& scene, int threads, uint32_t spp) {
  set_thread_count(threads);
  const PtSettings ps = small_settings();
  const PathTracer pt(scene, ps);
  Accumulator acc(ps.width, ps.height);
  pt.render(acc, spp);
  set_thread_count(0);
  return acc;
}

bool same_bytes(const Accumulator& a, const Accumulator& b) {
  return a.samples() == b.samples() && a.sums().size() == b.sums().size() &&
         std::memcmp(a.sums().data(), b.sums().data(), a.sums().size() * sizeof(double)) == 0;
}

TEST(Determinism, SameBytesFor1And2And8Threads) {
  const Scene scene = test::demo_room();
  const Accumulator one = render_with_threads(scene, 1, 3);
  const Accumulator two = render_with_threads(scene, 2, 3);
  const Accumulator eight = render_with_threads(scene, 8, 3);
  EXPECT_TRUE(same_bytes(one, two));
  EXPECT_TRUE(same_bytes(one, eight));
  // The scene really produces every AOV (so the comparison covers them).
  for (int a = 0; a < kAovCount; ++a) {
    if (a == kParticles) continue;  // the room has no fire
    double sum = 0.0;
    for (float v : one.mean(Aov(a)).data) sum += double(v);
    EXPECT_GT(sum, 0.0) << kAovNames[a];
  }
}

TEST(Determinism, PassesAppendedLaterGiveTheSameBytes) {
  const Scene scene = test::demo_room();
  const PtSettings ps = small_settings();
  const PathTracer pt(scene, ps);
  Accumulator split(ps.width, ps.height), whole(ps.width, ps.height);
  pt.render(split, 1);
  pt.render(split, 3);
  pt.render(whole, 3);
  EXPECT_TRUE(same_bytes(split, whole));
}

bool same_sample(const PathSample& a, const PathSample& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Determinism, FirstVertexReusedGivesTheSameSamples) {
  const Scene scene = test::demo_room();
  const PtSettings ps = small_settings();
  const EmbreeScene rt(scene);
  const EmissiveTriangles lights(scene);
  const Integrator integrator(scene, rt, lights, ps);
  Accumulator reference(ps.width, ps.height);
  int differ = 0, continuing = 0;
  RayCounts anew, reused;
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) {
      const Integrator::FirstVertex first = integrator.first_vertex(x, y, reused);
      continuing += first.continues;
      for (uint32_t s = 0; s < 3; ++s) {
        const PathSample a = integrator.trace(x, y, s, anew);
        differ += !same_sample(a, integrator.trace(first, x, y, s, reused));
        reference.add(x, y, s, a);
      }
    }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(continuing, ps.width * ps.height / 2);  // most pixels see the room, not the void
  // One camera ray per pixel instead of one per sample; the BSDF rays are the same.
  EXPECT_EQ(anew.primary, uint64_t(3 * ps.width * ps.height));
  EXPECT_EQ(reused.primary, uint64_t(ps.width * ps.height));
  EXPECT_EQ(anew.secondary, reused.secondary);
  EXPECT_LT(reused.shadow, anew.shadow);  // the first vertex's punctual shadow rays, once per pixel
  // PathTracer::render keeps the first vertices across its passes: the same sums.
  reference.set_samples(3);
  Accumulator rendered(ps.width, ps.height);
  PathTracer(scene, ps).render(rendered, 3);
  EXPECT_TRUE(same_bytes(rendered, reference));
}

TEST(Determinism, SeedChangesTheNoise) {
  const Scene scene = test::demo_room();
  PtSettings ps = small_settings();
  Accumulator a(ps.width, ps.height), b(ps.width, ps.height);
  PathTracer(scene, ps).render(a, 2);
  ps.seed = 4;
  PathTracer(scene, ps).render(b, 2);
  EXPECT_FALSE(same_bytes(a, b));
  // ... but not the noise-free direct term (pixel-centre rays, delta lights).
  EXPECT_EQ(a.mean(kDirect).data, b.mean(kDirect).data);
}

}  // namespace
}  // namespace vct::pt
