// The tie freedom of an engine's PCF (issue 39; freedoms/shadow_ties.h, snap_visibility.h): a
// filter-then-compare tap may flip where the point's depth lies within the filter weights' 8-bit
// freedom of the blended depth (a GL with 8-bit weights flips it: the freedom is needed), and not
// one step beyond it (an engine that compares first instead is caught there). On a real map,
// under every declared variant, the reference's own lookup lies in its ranges.
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "core/pcf_taps.h"
#include "freedoms/shadow_ties.h"
#include "freedoms/snap_visibility.h"
#include "scene/gltf_loader.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

// 4 x 4 texels over NDC = world; columns 0, 1 store 0.2, columns 2, 3 store 1.0.
ShadowMap step_map() {
  ShadowMap m;
  m.view_proj = mat4(1.0f);
  m.depth = Image(4, 4, 1);
  for (int row = 0; row < 4; ++row)
    for (int x = 0; x < 4; ++x) m.depth.at(x, row, 0) = x >= 2 ? 1.0f : 0.2f;
  return m;
}

VctSettings filter_first() {
  VctSettings s;
  s.pcf_taps = "0,0";
  s.shadow_bias = 0.0f;
  s.shadow_normal_offset = 0.0f;
  s.shadow_compare = ShadowCompare::Linear;
  s.shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  return s;
}

Light spot() {
  Light l;
  l.kind = LightKind::Spot;
  return l;
}

// The point at texel column u (y 0.1, window depth z): NDC x = u / 2 - 1, z = 2 z - 1.
vec3 at(float u, float z) { return vec3(u / 2.0f - 1.0f, 0.1f, 2.0f * z - 1.0f); }

// Between column 1's and column 2's centres D = 0.2 + 0.8 a, a = u - 1.5. The point at z = 0.601
// is lit where a >= 0.50125. At u = 2.003 (a = 0.503) the reference blends D = 0.6024 (lit); a GL
// whose weights keep 8 bits (a truncated to 128/256 = 0.5: D = 0.6) shadows it.
TEST(EnginePcfTies, FilteredTapMayFlipWithinTheWeightsEightBits) {
  const ShadowMap m = step_map();
  const VctSettings s = filter_first();
  const vec3 p = at(2.003f, 0.601f);
  EXPECT_EQ(shadow_visibility(m, p, s), 1.0f);
  const float a_gl = std::floor(0.503f * 256.0f) / 256.0f;
  const float d_gl = (1.0f - a_gl) * 0.2f + a_gl * 1.0f;
  ASSERT_GT(0.601f, d_gl) << "the 8-bit GL must shadow it for the test to mean anything";
  const VisibilityRange r = light_visibility_range(m, spot(), p, s);
  EXPECT_EQ(r.lo, 0.0f);
  EXPECT_EQ(r.hi, 1.0f);
}

// Ten 8-bit steps further (a = 0.54) the tap is lit for every admissible lookup; an engine that
// compares first (0.54 of a lit tap) lies outside that range, as does one that forgot the bias sign.
TEST(EnginePcfTies, BeyondTheFreedomTheTapIsFixedAndCompareFirstIsCaught) {
  const ShadowMap m = step_map();
  VctSettings s = filter_first();
  const vec3 p = at(2.04f, 0.601f);
  const VisibilityRange r = light_visibility_range(m, spot(), p, s);
  EXPECT_EQ(r.lo, 1.0f);
  EXPECT_EQ(r.hi, 1.0f);
  s.shadow_filter_order = ShadowFilterOrder::CompareThenFilter;
  const float compared_first = shadow_visibility(m, p, s);
  EXPECT_NEAR(compared_first, 0.54f, 1e-5f);
  EXPECT_LT(compared_first, r.lo);
  // And the shadowed side: a = 0.46, D = 0.568 < 0.601 for every admissible lookup.
  const VisibilityRange dark = light_visibility_range(m, spot(), at(1.96f, 0.601f), filter_first());
  EXPECT_EQ(dark.lo, 0.0f);
  EXPECT_EQ(dark.hi, 0.0f);
}

// A shadowed border: the tap that reads past the edge is fixed (no freedom from the border), and
// within a rounding of the edge it may read either side.
TEST(EnginePcfTies, BorderTexelsAreComparedAtTheBordersDepth) {
  ShadowMap m = step_map();
  VctSettings s;
  s.pcf_taps = "1,0";
  s.shadow_bias = 0.0f;
  s.shadow_normal_offset = 0.0f;
  s.shadow_border = ShadowBorder::Shadowed;
  const VisibilityRange past = light_visibility_range(m, spot(), at(3.5f, 0.6f), s);  // reads column 4
  EXPECT_EQ(past.lo, 0.0f);
  EXPECT_EQ(past.hi, 0.0f);
  const VisibilityRange edge = light_visibility_range(m, spot(), at(3.0f, 0.6f), s);  // 4.0: column 3 or 4
  EXPECT_EQ(edge.lo, 0.0f);
  EXPECT_EQ(edge.hi, 1.0f);
  s.shadow_border = ShadowBorder::Clamp;
  const VisibilityRange clamped = light_visibility_range(m, spot(), at(3.5f, 0.6f), s);
  EXPECT_EQ(clamped.lo, 1.0f);
}

// The built-in box's spot under gidemo's voxel-pass PCF (UV taps per 1/w, filter then compare,
// shadowed border) and two other mixes: at random points the reference's lookup lies in its tie
// range, and over random snap parallelograms every sampled point's lookup lies in the
// parallelogram's range; the ranges are rarely open.
TEST(EnginePcfTies, RangesHoldTheReferencesLookupUnderEveryVariant) {
  const Scene scene = load_scene("");
  ASSERT_FALSE(scene.lights.empty());
  ASSERT_FALSE(scene.lights[0].is_point());
  std::vector<VctSettings> variants(3);
  for (VctSettings& s : variants) {
    s.shadow_map_size = 128;
    s.shadow_normal_offset = 0.0f;
  }
  // gidemo's voxelize.frag shadow(): {-1, -1/3, 1/3} x voxelSize / 2 (N = 64) in UV per 1/w.
  variants[0].pcf_taps = "-0.0078125,-0.0078125 -0.0026042,-0.0078125 0.0026042,-0.0078125 "
                         "-0.0078125,-0.0026042 -0.0026042,-0.0026042 0.0026042,-0.0026042 "
                         "-0.0078125,0.0026042 -0.0026042,0.0026042 0.0026042,0.0026042";
  variants[0].pcf_tap_unit = PcfTapUnit::Uv;
  variants[0].pcf_tap_scale = PcfTapScale::InvW;
  variants[0].shadow_compare = ShadowCompare::Linear;
  variants[0].shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  variants[0].shadow_border = ShadowBorder::Shadowed;
  variants[1].pcf_taps = "-1.5,0.5 0.5,-1.5 0,0";
  variants[1].shadow_compare = ShadowCompare::Linear;
  variants[1].shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  variants[1].shadow_border = ShadowBorder::Lit;
  variants[2].pcf_taps = "-0.01,0 0.01,0";
  variants[2].pcf_tap_unit = PcfTapUnit::Uv;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const Light& light = scene.lights[0];
  for (size_t k = 0; k < variants.size(); ++k) {
    const VctSettings& s = variants[k];
    const std::vector<ShadowMap> maps = render_shadow_maps(scene, s);
    int open = 0, single = 0;
    const int n = 3000;
    for (int i = 0; i < n; ++i) {
      const vec3 p = scene.volume.to_world(vec3(unit(rng), unit(rng), unit(rng)));
      const float v = light_visibility(maps[0], light, p, s);
      const VisibilityRange r = light_visibility_range(maps[0], light, p, s);
      ASSERT_LE(r.lo, v) << k << " " << i;
      ASSERT_GE(r.hi, v) << k << " " << i;
      open += r.lo < r.hi;
      if (i % 10 != 0) continue;
      SnapParallelogram q;
      q.centre = p;
      q.du = vec3(0.003f * unit(rng), 0.0f, 0.001f * unit(rng));
      q.dv = vec3(0.0f, 0.003f * unit(rng), 0.0f);
      const VisibilityRange snap = snap_visibility_range(maps[0], light, q, s);
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; b <= 4; ++b) {
          const vec3 x = q.centre + (float(a) / 2.0f - 1.0f) * q.du + (float(b) / 2.0f - 1.0f) * q.dv;
          const float w = light_visibility(maps[0], light, x, s);
          ASSERT_GE(w, snap.lo) << k << " " << i << " " << a << "," << b;
          ASSERT_LE(w, snap.hi) << k << " " << i << " " << a << "," << b;
        }
      single += snap.lo == snap.hi;
    }
    std::printf("[engine pcf] variant %zu: %d of %d tie ranges open, %d of %d snap ranges single\n", k, open, n,
                single, n / 10);
    EXPECT_LT(open, n / 50) << k;
    EXPECT_GT(single, n / 10 * 8 / 10) << k;
  }
}

}  // namespace
}  // namespace vct
