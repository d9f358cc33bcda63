// Embree's 16-ray packets (EmbreeScene::intersect_packet / occluded_packet, used by
// Integrator::trace_packet at the first vertex) answer exactly as its single-ray queries: the same
// hit, distance, triangle and barycentrics bit for bit, for every lane of a partial packet, with
// inactive lanes left untraced — on the demo room (opaque geometry) and on the half-masked card
// (the alpha filter functions run on packets). Integrator::trace_packet over lanes of several
// pixels, some of whose paths end at their first vertex, gives trace()'s samples byte for byte.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "../ref/alpha_card_scene.h"
#include "pt/embree_scene.h"
#include "pt/emissive_lights.h"
#include "pt/integrator.h"
#include "pt/rng.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

using RayQuery = EmbreeScene::RayQuery;

/// Rays from one point (as a first vertex's) and from scattered points, random directions, some
/// short enough to stop before anything; every 5th lane inactive.
std::vector<RayQuery> probe_rays(const Scene& s, int count) {
  Pcg32 rng(11u, 5u);
  std::vector<RayQuery> rays;
  const vec3 centre = 0.5f * (s.bounds.lo + s.bounds.hi);
  for (int i = 0; i < count; ++i) {
    RayQuery q;
    q.org = (i / 16) % 2 == 0 ? centre
                              : s.bounds.lo + s.bounds.extent() * vec3(rng.next_float(), rng.next_float(), rng.next_float());
    const float z = 1.0f - 2.0f * rng.next_float(), phi = 2.0f * kPi * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    q.dir = vec3(r * std::cos(phi), r * std::sin(phi), z) * (0.5f + rng.next_float());
    q.tnear = 1e-4f;
    q.tfar = i % 3 == 0 ? 0.05f : 1e30f;
    q.active = i % 5 != 4;
    rays.push_back(q);
  }
  return rays;
}

bool same_hit(const Hit& a, const Hit& b) {
  return a.hit == b.hit && (!a.hit || (std::memcmp(&a.t, &b.t, sizeof a.t) == 0 && a.triangle == b.triangle &&
                                       std::memcmp(&a.b1, &b.b1, sizeof a.b1) == 0 &&
                                       std::memcmp(&a.b2, &b.b2, sizeof a.b2) == 0));
}

/// Packets of n = 16, 7 and 1 lanes over `rays`, against one query per ray. Returns the hits seen.
int expect_packets_match_single_rays(const EmbreeScene& rt, const std::vector<RayQuery>& rays) {
  int hits = 0;
  for (const int n : {EmbreeScene::kPacket, 7, 1})
    for (size_t first = 0; first + size_t(n) <= rays.size(); first += size_t(n)) {
      Hit packet_hits[EmbreeScene::kPacket];
      bool packet_occluded[EmbreeScene::kPacket];
      rt.intersect_packet(&rays[first], n, packet_hits);
      rt.occluded_packet(&rays[first], n, packet_occluded);
      for (int i = 0; i < n; ++i) {
        const RayQuery& q = rays[first + size_t(i)];
        const Hit single = q.active ? rt.intersect(q.org, q.dir, q.tnear, q.tfar) : Hit{};
        const bool single_occluded = q.active && rt.occluded(q.org, q.dir, q.tnear, q.tfar);
        EXPECT_TRUE(same_hit(packet_hits[i], single)) << "ray " << first + size_t(i) << " of packet size " << n;
        EXPECT_EQ(packet_occluded[i], single_occluded) << "ray " << first + size_t(i) << " of packet size " << n;
        hits += single.hit;
      }
    }
  return hits;
}

TEST(EmbreePacket, AnswersAsSingleRaysOnOpaqueGeometry) {
  const Scene s = test::demo_room();
  const EmbreeScene rt(s);
  const std::vector<RayQuery> rays = probe_rays(s, 16 * 40);
  const int hits = expect_packets_match_single_rays(rt, rays);
  EXPECT_GT(hits, 600);  // both hits and misses (short rays, inactive lanes) are compared
  EXPECT_LT(hits, 3 * 640);
}

TEST(EmbreePacket, AnswersAsSingleRaysThroughAlphaFilters) {
  const Scene s = vct::test::half_masked_card(true);
  const EmbreeScene rt(s);
  // Rays at the card from both sides, half of them through its cut-away half.
  std::vector<RayQuery> rays;
  Pcg32 rng(3u, 9u);
  for (int i = 0; i < 16 * 20; ++i) {
    RayQuery q;
    q.org = vec3(-1.25f + 2.5f * rng.next_float(), -1.25f + 2.5f * rng.next_float(), i % 2 ? 2.0f : -0.5f);
    q.dir = vec3(0.05f * (rng.next_float() - 0.5f), 0.05f * (rng.next_float() - 0.5f), i % 2 ? -1.0f : 1.0f);
    q.tfar = 10.0f;
    q.active = i % 9 != 8;
    rays.push_back(q);
  }
  EXPECT_GT(expect_packets_match_single_rays(rt, rays), 300);
}

TEST(EmbreePacket, TracePacketIsTraceForLanesOfSeveralPixels) {
  const Scene scene = test::demo_room();
  PtSettings ps;
  ps.width = 12;
  ps.height = 10;
  ps.max_depth = 5;
  ps.rr_start_depth = 2;
  const EmbreeScene rt(scene);
  const EmissiveTriangles lights(scene);
  const Integrator integrator(scene, rt, lights, ps);
  RayCounts counts;
  std::vector<Integrator::FirstVertex> first;
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) first.push_back(integrator.first_vertex(x, y, counts));
  // A first vertex whose path ends there (a camera ray into the void, or max_depth reached): its
  // samples are its light alone.
  Integrator::FirstVertex ends;
  ends.out.aov[kEmission] = ends.out.aov[kFull] = vec3(0.25f, 0.5f, 0.75f);
  // Lanes of every pixel, three samples each, in packets of 16 that cut across pixels and rows;
  // every 7th pixel's lanes start from `ends`.
  std::vector<Integrator::Lane> lanes;
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) {
      const int pixel = y * ps.width + x;
      for (uint32_t s = 0; s < 3; ++s)
        lanes.push_back(Integrator::Lane{pixel % 7 == 3 ? &ends : &first[size_t(pixel)], x, y, s});
    }
  int differ = 0, missing = 0;
  RayCounts packet_counts, single_counts;
  for (size_t a = 0; a < lanes.size(); a += EmbreeScene::kPacket) {
    const int n = int(std::min<size_t>(EmbreeScene::kPacket, lanes.size() - a));
    PathSample out[EmbreeScene::kPacket];
    integrator.trace_packet(&lanes[a], n, out, packet_counts);
    for (int i = 0; i < n; ++i) {
      const Integrator::Lane& l = lanes[a + size_t(i)];
      const PathSample single = integrator.trace(*l.first, l.x, l.y, l.sample, single_counts);
      differ += std::memcmp(&single, &out[i], sizeof single) != 0;
      missing += !l.first->continues;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(missing, 0);  // some lanes start from a vertex whose path ends there
  EXPECT_EQ(packet_counts.secondary, single_counts.secondary);
  EXPECT_EQ(packet_counts.shadow, single_counts.shadow);
}

}  // namespace
}  // namespace vct::pt
