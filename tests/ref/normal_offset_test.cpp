// Normal-offset shadow bias (stages/shadow_map.h, docs/pipeline.md "Normal offset"): the lookup
// point's closed form, the lamp-near-a-wall case of issue 35 (a point lamp 0.4 m in front of a
// wall, acne under the constant bias alone) lit everywhere with the default, and the judge's
// freedoms (shadow_ties.h, snap_visibility.h) holding the offset lookups' values.
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>

#include "freedoms/reference_frame.h"
#include "freedoms/shadow_ties.h"
#include "freedoms/snap_visibility.h"
#include "lamp_near_a_wall.h"
#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

Settings wall_settings(float offset) {
  Settings s;
  s.vct.width = s.vct.height = 96;
  s.vct.shadow_map_size = 1024;  // validate's size: the constant bias's acne reaches 1.05 m here
  s.vct.grid = 32;
  s.vct.shadow_normal_offset = offset;
  s.threads = 2;
  return s;
}

TEST(NormalOffset, LookupPointIsTheClosedForm) {
  // A point 1.2 m along -z of a point light (face 5, -z) on a plane whose normal is the face's
  // x axis: |n.r0| / |r0|^2 = 1 (the 90 degree face: |r0| = 1), n.r1 = 0, w = the depth 1.2, so the
  // offset is R (2 / S) w = 1.5 x 2 / 256 x 1.2 with 3 x 3 nearest taps (R = 1.5).
  const Scene scene = test::lamp_near_a_wall();
  VctSettings s;
  s.shadow_map_size = 256;
  const ShadowMap map = render_shadow_maps(scene, s)[0];
  EXPECT_EQ(pcf_reach(s), vec2(1.5f));
  const vec3 p = scene.lights[0].position + vec3(0.0f, 0.0f, -1.2f), n(1.0f, 0.0f, 0.0f);
  const vec3 q = shadow_lookup_point(map, scene.lights[0], p, n, s);
  EXPECT_NEAR(q.x - p.x, 1.5 * 2.0 / 256.0 * 1.2, 1e-6);
  EXPECT_EQ(q.y, p.y);
  EXPECT_EQ(q.z, p.z);
  s.shadow_normal_offset = 2.0f;  // the setting scales it
  EXPECT_NEAR(shadow_lookup_point(map, scene.lights[0], p, n, s).x - p.x, 2.0 * 1.5 * 2.0 / 256.0 * 1.2, 2e-6);
  s.shadow_normal_offset = 0.0f;  // off: the point itself
  EXPECT_EQ(shadow_lookup_point(map, scene.lights[0], p, n, s), p);
}

TEST(NormalOffset, LampNearAWallIsLitEverywhere) {
  const Scene scene = test::lamp_near_a_wall();
  double fraction[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const Settings s = wall_settings(k == 0 ? 0.0f : 1.0f);
    const FrameResult f = render_ref_frame(scene, s);
    fraction[k] = test::lit_fraction(scene, s.vct, f.gbuffer, f.images.direct);
  }
  std::printf("[normal offset] lamp 0.4 m from a wall, 1024^2 cube: lit %.4f of the wall without the offset, %.4f with\n",
              fraction[0], fraction[1]);
  EXPECT_LT(fraction[0], 0.9) << "the constant bias alone must show the acne for the test to mean anything";
  EXPECT_EQ(fraction[1], 1.0);
}

// The judge's freedoms hold the offset lookups: at every wall pixel the direct tie range's
// visibility contains the lookup's value, and over snap parallelograms on the wall (up to 4 mm)
// every sampled point's offset lookup lies in the parallelogram's range.
TEST(NormalOffset, TieRangesHoldTheOffsetLookups) {
  const Scene scene = test::lamp_near_a_wall();
  VctSettings s = wall_settings(1.0f).vct;
  s.shadow_map_size = 256;
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, s);
  const Light& light = scene.lights[0];
  const vec3 n(0.0f, 0.0f, 1.0f);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int single = 0;
  for (int k = 0; k < 1000; ++k) {
    const vec3 p(4.0f * unit(rng) - 2.0f, 3.0f * unit(rng), -1.0f);
    const float v = surface_visibility(maps[0], light, p, n, s);
    const VisibilityRange r = surface_visibility_range(maps[0], light, p, n, s);
    ASSERT_GE(v, r.lo) << k;
    ASSERT_LE(v, r.hi) << k;
    SnapParallelogram q;
    q.centre = p;
    q.du = vec3(0.004f * unit(rng), 0.0f, 0.0f);
    q.dv = vec3(0.0f, 0.004f * unit(rng), 0.0f);
    const VisibilityRange snap = snap_surface_visibility_range(maps[0], light, q, n, s);
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        const vec3 at = q.centre + (float(i) / 2.0f - 1.0f) * q.du + (float(j) / 2.0f - 1.0f) * q.dv;
        const float w = surface_visibility(maps[0], light, at, n, s);
        ASSERT_GE(w, snap.lo) << k << " " << i << "," << j;
        ASSERT_LE(w, snap.hi) << k << " " << i << "," << j;
      }
    single += snap.lo == snap.hi ? 1 : 0;
  }
  std::printf("[normal offset] %d of 1000 snap ranges on the wall a single value\n", single);
  EXPECT_GT(single, 900);
}

}  // namespace
}  // namespace vct
