// An engine's PCF beyond taps and compare (issue 39): filter-then-compare, UV tap offsets, taps per
// 1/w, the map's border and the voxelizer's own taps, each on a hand-made map with values worked
// by hand. The map: 8x8, orthographic identity (world = NDC), columns 0..3 occluded at depth 0.3,
// the rest at 1; the point at world z 0.2 (window depth 0.6), behind the occluder's depth.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/pcf_taps.h"
#include "core/settings_table.h"
#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/inject.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

ShadowMap left_half_occluded(float w = 1.0f) {
  ShadowMap m;
  m.view_proj = mat4(w);  // clip = w (x, y, z, 1): the NDC of the identity, clip w = w
  m.depth = Image(8, 8, 1, 1.0f);
  for (int row = 0; row < 8; ++row)
    for (int x = 0; x < 4; ++x) m.depth.at(x, row, 0) = 0.3f;
  return m;
}
vec3 behind_at_column(float u) { return vec3(u / 8.0f * 2.0f - 1.0f, 0.1f, 0.2f); }

VctSettings one_tap(const char* taps = "0,0") {
  VctSettings s;
  s.pcf_taps = taps;
  return s;
}

// GL LINEAR on a plain sampler2D: D = (1 - a) d3 + a d4 with a = frac(u - 1/2), lit iff
// 0.6 <= D + 0.0005; on a shadow sampler the compares are weighted instead.
TEST(EnginePcf, FilterThenCompareBlendsTheDepthsAndComparesOnce) {
  const ShadowMap m = left_half_occluded();
  VctSettings s = one_tap();
  s.shadow_compare = ShadowCompare::Linear;
  s.shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(4.25f), s), 1.0f);  // a 0.75: D = 0.825
  EXPECT_EQ(shadow_visibility(m, behind_at_column(4.0f), s), 1.0f);   // a 0.5:  D = 0.65
  EXPECT_EQ(shadow_visibility(m, behind_at_column(3.9f), s), 0.0f);   // a 0.4:  D = 0.58
  EXPECT_EQ(shadow_visibility(m, behind_at_column(3.75f), s), 0.0f);  // a 0.25: D = 0.475
  s.shadow_filter_order = ShadowFilterOrder::CompareThenFilter;       // the shadow sampler's
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(4.25f), s), 0.75f);
  EXPECT_FLOAT_EQ(shadow_visibility(m, behind_at_column(3.75f), s), 0.25f);
  // Nearest reads one texel: the order makes no difference.
  s.shadow_compare = ShadowCompare::Nearest;
  s.shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(3.9f), s), 0.0f);
  EXPECT_EQ(shadow_visibility(m, behind_at_column(4.1f), s), 1.0f);
}

TEST(EnginePcf, UvOffsetsAreTextureCoordinates) {
  const ShadowMap m = left_half_occluded();
  VctSettings s = one_tap("0.125,0");  // 1/8 of the map: one texel
  EXPECT_EQ(shadow_visibility(m, behind_at_column(3.5f), s), 0.0f);  // texels: 3.625, column 3
  s.pcf_tap_unit = PcfTapUnit::Uv;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(3.5f), s), 1.0f);  // 4.5, column 4
  EXPECT_EQ(tap_positions(3.5f, 2.0f, s, 8, 1.0f), (std::vector<vec2>{{4.5f, 2.0f}}));
  EXPECT_EQ(tap_positions(3.5f, 2.0f, s, 16, 1.0f), (std::vector<vec2>{{5.5f, 2.0f}}));
}

TEST(EnginePcf, InverseWTapsShrinkWithTheClipW) {
  const ShadowMap m = left_half_occluded(2.0f);  // the same NDC, clip w = 2
  VctSettings s = one_tap("-2,0");
  s.shadow_normal_offset = 0.0f;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(5.5f), s), 0.0f);  // 3.5: column 3
  s.pcf_tap_scale = PcfTapScale::InvW;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(5.5f), s), 1.0f);  // 5.5 - 2/2 = 4.5: column 4
  // gidemo's voxel taps: UV offsets per 1/w, (i/3) 2 - 1 times voxelSize / 2 (N = 64).
  s.pcf_tap_unit = PcfTapUnit::Uv;
  s.pcf_taps = "-0.0078125,0";
  EXPECT_EQ(tap_positions(100.0f, 0.0f, s, 2048, 0.5f), (std::vector<vec2>{{68.0f, 0.0f}}));  // 16 / 0.5 texels
  // The normal offset is derived for taps fixed in texels: refused with them.
  Settings bad;
  bad.vct.pcf_tap_scale = PcfTapScale::InvW;
  EXPECT_THROW(validate_settings(bad), InputError);
}

TEST(EnginePcf, BorderReadsEdgeTexelLitOrShadowed) {
  const ShadowMap m = left_half_occluded();
  VctSettings s = one_tap("-2,0");  // from column 0 to column -2, past the edge
  EXPECT_EQ(shadow_visibility(m, behind_at_column(0.5f), s), 0.0f);  // clamp: column 0 (0.3)
  s.shadow_border = ShadowBorder::Lit;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(0.5f), s), 1.0f);  // depth 1
  s.pcf_taps = "2,0";  // from column 7 to column 9
  s.shadow_border = ShadowBorder::Clamp;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(7.5f), s), 1.0f);  // clamp: column 7 (1)
  s.shadow_border = ShadowBorder::Shadowed;
  EXPECT_EQ(shadow_visibility(m, behind_at_column(7.5f), s), 0.0f);  // depth 0
  // Filtered first, the border's depth enters the blend: at u = 8, a = 0.5 between column 7 (1)
  // and the border (0): D = 0.5 < 0.6.
  s.pcf_taps = "0,0";
  s.shadow_compare = ShadowCompare::Linear;
  s.shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  EXPECT_EQ(shadow_visibility(m, vec3(0.99999f, 0.1f, 0.2f), s), 0.0f);
  s.shadow_border = ShadowBorder::Clamp;
  EXPECT_EQ(shadow_visibility(m, vec3(0.99999f, 0.1f, 0.2f), s), 1.0f);
}

TEST(EnginePcf, VoxelPassTakesItsOwnTaps) {
  VctSettings s = one_tap("1,0");
  EXPECT_EQ(voxel_pass_settings(s).pcf_taps, "1,0");  // none declared: the frame's
  s.voxel_pcf_taps = "-1,0 1,0";
  EXPECT_EQ(voxel_pass_settings(s).pcf_taps, "-1,0 1,0");
  EXPECT_EQ(voxel_pass_settings(s).voxel_pcf_taps, "-1,0 1,0");
  Settings bad;
  bad.vct.voxel_pcf_taps = "1;0";
  try {
    validate_settings(bad);
    ADD_FAILURE() << "a malformed voxel_pcf_taps passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("voxel_pcf_taps"), std::string::npos) << e.what();
  }
  // voxel_pcf = oracle: the voxelizer runs the oracle's PCF whatever the frame declares.
  VctSettings framed = one_tap("-0.01,0");
  framed.shadow_compare = ShadowCompare::Linear;
  framed.shadow_filter_order = ShadowFilterOrder::FilterThenCompare;
  framed.pcf_tap_unit = PcfTapUnit::Uv;
  framed.shadow_border = ShadowBorder::Shadowed;
  framed.voxel_pcf = VoxelPcf::Oracle;
  const VctSettings v = voxel_pass_settings(framed);
  EXPECT_EQ(v.pcf_taps, "");
  EXPECT_EQ(v.shadow_compare, ShadowCompare::Nearest);
  EXPECT_EQ(v.shadow_filter_order, ShadowFilterOrder::CompareThenFilter);
  EXPECT_EQ(v.pcf_tap_unit, PcfTapUnit::Texel);
  EXPECT_EQ(v.shadow_border, ShadowBorder::Clamp);
  EXPECT_EQ(tap_positions(10.0f, 10.0f, v, 64, 1.0f).size(), 9u);  // the 3x3 square
  Settings both;
  both.vct.voxel_pcf = VoxelPcf::Oracle;
  both.vct.voxel_pcf_taps = "0,0";
  EXPECT_THROW(validate_settings(both), InputError);
  const Settings t = with_setting(Settings{}, "shadow_filter_order", "filter_then_compare", "--set");
  EXPECT_EQ(t.vct.shadow_filter_order, ShadowFilterOrder::FilterThenCompare);
  EXPECT_EQ(with_setting(Settings{}, "shadow_border", "shadowed", "--set").vct.shadow_border, ShadowBorder::Shadowed);
}

// A stage set's manifest carries the PCF as its "settings" (vct config-from-manifest reads them as
// VctSettings JSON): gidemo's voxel-pass description, written and read back key by key.
TEST(EnginePcf, TheDescriptionRoundTripsThroughSettingsJson) {
  const nlohmann::json manifest_settings = {{"shadow_compare", "linear"},        {"shadow_filter_order", "filter_then_compare"},
                                            {"pcf_tap_unit", "uv"},             {"pcf_tap_scale", "inv_w"},
                                            {"shadow_border", "shadowed"},      {"shadow_normal_offset", 0},
                                            {"voxel_pcf_taps", "-0.0078125,0"}, {"pcf_taps", "0.0009765625,0"}};
  nlohmann::json j = VctSettings();
  j.merge_patch(manifest_settings);
  const VctSettings s = j.get<VctSettings>();
  EXPECT_EQ(s.shadow_filter_order, ShadowFilterOrder::FilterThenCompare);
  EXPECT_EQ(s.pcf_tap_unit, PcfTapUnit::Uv);
  EXPECT_EQ(s.pcf_tap_scale, PcfTapScale::InvW);
  EXPECT_EQ(s.shadow_border, ShadowBorder::Shadowed);
  EXPECT_EQ(s.voxel_pcf_taps, "-0.0078125,0");
  const nlohmann::json back = s;
  for (const auto& [key, value] : manifest_settings.items()) EXPECT_EQ(back.at(key), value) << key;
}

// The voxelizer's lookups run with voxel_pcf_taps (fragment_radiance): a floor under a spot with a
// small occluder between them, its shadow's edge on the floor. Injected light with voxel taps
// T equals injected light with frame taps T, and differs from the frame taps' own.
TEST(EnginePcf, LightInjectionUsesTheVoxelTaps) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.8f));
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  test::add_quad(s, {-0.3f, 0.6f, -0.3f}, {0.3f, 0.6f, -0.3f}, {0.3f, 0.6f, 0.3f}, {-0.3f, 0.6f, 0.3f}, {0, 1, 0}, m);
  Light spot;
  spot.position = vec3(0.05f, 1.5f, 0.02f);
  spot.direction = vec3(0.0f, -1.0f, 0.0f);
  spot.outer_cone_angle = 0.9f;
  spot.intensity = 10.0f;
  s.lights.push_back(spot);
  s.volume = fit_volume(s.bounds);
  VctSettings frame;
  frame.grid = 16;
  frame.shadow_map_size = 64;
  frame.pcf_taps = "0,0";
  const std::vector<ShadowMap> maps = render_shadow_maps(s, frame);
  const Voxelization vox = voxelize_gpu_rule(s, frame.grid, 4);
  VctSettings voxel = frame;
  voxel.voxel_pcf_taps = "6,6";
  VctSettings moved = frame;
  moved.pcf_taps = "6,6";
  const std::vector<vec3> own = fragment_radiance(s, vox, maps, frame);
  const std::vector<vec3> declared = fragment_radiance(s, vox, maps, voxel);
  const std::vector<vec3> expected = fragment_radiance(s, vox, maps, moved);
  ASSERT_EQ(declared.size(), expected.size());
  int differ = 0;
  for (size_t i = 0; i < declared.size(); ++i) {
    EXPECT_EQ(declared[i], expected[i]) << i;
    differ += declared[i] != own[i];
  }
  EXPECT_GT(differ, 0) << "the 6-texel shift moved no fragment across the shadow's edge";
}

}  // namespace
}  // namespace vct
