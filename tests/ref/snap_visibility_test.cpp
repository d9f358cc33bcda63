// The PCF visibility over a fragment's snap parallelogram (freedoms/snap_visibility.h): a hand-made
// map where the only lit part lies inside the parallelogram, away from every corner (what the
// corner-only slack missed on atrium, docs/compare.md "Voxel shading slack"), and every point of
// many parallelograms on a real scene's spot and point light maps inside the range.
#include <gtest/gtest.h>
#include <random>

#include "freedoms/snap_visibility.h"
#include "stage_test_scene.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

vec3 point_at(const SnapParallelogram& q, float a, float b) { return q.centre + a * q.du + b * q.dv; }

// view_proj = identity: NDC is the world point, u = (x + 1) 32 on a 64^2 map, window depth
// z / 2 + 1/2. Column 10 stores depth 0 (every point behind it: shadowed), column 11 stores 1/2.
// One tap (pcf_kernel 1), no bias. Over the parallelogram u = 10.98 + 0.1 (a - b) and window depth
// 1/2 + d (1.2 + a + b): the tap reads column 11 only where a - b >= 0.2 and is lit there only
// where a + b <= -1.2 — a wedge that holds no corner: (-0.3, -1) is lit, the corners and the
// centre are not.
TEST(SnapVisibility, ALitWedgeInsideTheParallelogramIsFoundWhereNoCornerShowsIt) {
  ShadowMap map;
  map.depth = Image(64, 64, 1);
  for (int y = 0; y < 64; ++y) *map.depth.pixel(11, y) = 0.5f;
  Light sun;
  sun.kind = LightKind::Directional;
  VctSettings s;
  s.pcf_kernel = 1;
  s.shadow_bias = 0.0f;
  const float d = 1e-3f;
  SnapParallelogram q;
  q.centre = vec3(10.98f / 32.0f - 1.0f, 20.5f / 32.0f - 1.0f, 2.0f * d * 1.2f);
  q.du = vec3(0.1f / 32.0f, 0.0f, 2.0f * d);
  q.dv = vec3(-0.1f / 32.0f, 0.0f, 2.0f * d);
  for (const float a : {-1.0f, 1.0f})
    for (const float b : {-1.0f, 1.0f}) EXPECT_EQ(light_visibility(map, sun, point_at(q, a, b), s), 0.0f);
  EXPECT_EQ(light_visibility(map, sun, q.centre, s), 0.0f);
  EXPECT_EQ(light_visibility(map, sun, point_at(q, -0.3f, -1.0f), s), 1.0f);
  const VisibilityRange r = snap_visibility_range(map, sun, q, s);
  EXPECT_EQ(r.lo, 0.0f);
  EXPECT_EQ(r.hi, 1.0f);
  // Moved off the wedge (the depth 0.002 higher everywhere): shadowed at every point, and said so.
  q.centre.z += 4.0f * d;
  const VisibilityRange off = snap_visibility_range(map, sun, q, s);
  EXPECT_EQ(off.lo, 0.0f);
  EXPECT_EQ(off.hi, 0.0f);
  // Wholly inside column 11 and below its depth: lit everywhere.
  q.centre = vec3(11.5f / 32.0f - 1.0f, 20.5f / 32.0f - 1.0f, -0.5f);
  const VisibilityRange lit = snap_visibility_range(map, sun, q, s);
  EXPECT_EQ(lit.lo, 1.0f);
  EXPECT_EQ(lit.hi, 1.0f);
}

// Every point of a parallelogram looks up a visibility inside its range: 2000 random
// parallelograms (sides up to 4 mm, 10-20 shadow texels) on the surfaces of the stage room, lit by
// its spot (2D map) and by a point light (cube map, taps past face edges), each sampled on an
// 11 x 11 grid. The ranges are not vacuous: on most parallelograms they are a single value, and
// no range is wider than what its own samples plus the lookup's float ties explain (a plane
// lying in the open never ties with its own stored depth).
TEST(SnapVisibility, EveryPointOfTheParallelogramLiesInTheRange) {
  for (const bool point : {false, true}) {
    Scene scene = test::stage_room();
    if (point) {
      scene.lights[0].kind = LightKind::Point;
      scene.lights[0].position = vec3(0.35f, 1.2f, 0.3f);
    }
    VctSettings s;
    s.shadow_map_size = 256;
    const std::vector<ShadowMap> maps = render_shadow_maps(scene, s);
    const Light& light = scene.lights[0];
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int single = 0, partial = 0;
    for (int n = 0; n < 2000; ++n) {
      const uint32_t t = uint32_t(unit(rng) * float(scene.triangles.size() - 1));
      const uvec3 tri = scene.triangles[t];
      const vec3 p0 = scene.positions[tri.x], e1 = scene.positions[tri.y] - p0, e2 = scene.positions[tri.z] - p0;
      float b1 = unit(rng), b2 = unit(rng);
      if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
      SnapParallelogram q;
      q.centre = p0 + b1 * e1 + b2 * e2;
      q.du = 0.004f * unit(rng) * glm::normalize(e1);
      q.dv = 0.004f * unit(rng) * glm::normalize(e2);
      const VisibilityRange r = snap_visibility_range(maps[0], light, q, s);
      ASSERT_LE(r.lo, r.hi);
      float seen_lo = 1.0f, seen_hi = 0.0f;
      for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
          const float v = light_visibility(maps[0], light, point_at(q, float(i) / 5.0f - 1.0f, float(j) / 5.0f - 1.0f), s);
          ASSERT_GE(v, r.lo) << (point ? "point" : "spot") << " parallelogram " << n << " sample " << i << "," << j;
          ASSERT_LE(v, r.hi) << (point ? "point" : "spot") << " parallelogram " << n << " sample " << i << "," << j;
          seen_lo = std::min(seen_lo, v), seen_hi = std::max(seen_hi, v);
        }
      single += r.lo == r.hi ? 1 : 0;
      partial += seen_lo < seen_hi ? 1 : 0;
    }
    std::printf("[snap visibility] %s light: %d of 2000 ranges a single value; %d with two values among the samples\n",
                point ? "point" : "spot", single, partial);
    EXPECT_GT(partial, 20) << "the parallelograms must cross shadow edges for the test to mean anything";
    EXPECT_GT(single, 1500);
  }
}

}  // namespace
}  // namespace vct
