// The oracle's shortcuts (issue 37 item 5, docs/performance.md "The oracle's extras, mechanics
// only") give the long way's bits: evaluations left out where scene/surface.h says the material
// cannot tell them apart, positions without the rest of the surface, PCF taps without a vector.
#include <cstring>
#include <gtest/gtest.h>

#include "freedoms/raster_alternatives.h"
#include "freedoms/window_barycentrics.h"
#include "scene/surface.h"
#include "stage_test_scene.h"
#include "stages/gbuffer.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

bool same_bits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

bool same_material(const SurfaceMaterial& a, const SurfaceMaterial& b) {
  return same_bits(a.albedo, b.albedo) && same_bits(a.emission, b.emission) &&
         same_bits(a.shading_normal, b.shading_normal) && same_bits(a.specular_color, b.specular_color) &&
         std::memcmp(&a.metallic, &b.metallic, sizeof(float)) == 0 &&
         std::memcmp(&a.roughness, &b.roughness, sizeof(float)) == 0 &&
         std::memcmp(&a.specular_factor, &b.specular_factor, sizeof(float)) == 0 &&
         std::memcmp(&a.opacity, &b.opacity, sizeof(float)) == 0;
}

// Every field of SlotLods set away from the reference's own.
SlotLods other_lods(bool srgb_after_filter) {
  SlotLods l;
  for (double& lambda : l.lambda) lambda = 1.7;
  l.srgb_after_filter = srgb_after_filter;
  l.texel_shift = vec2(0.25f, -0.5f);
  l.normal_texel_offset = vec3(1.0f / 255.0f);
  l.srgb_decode_steps = 0.5f;
  return l;
}

// A camera-facing quad at z = -2 (stage_test_scene.h) with a 4x1 texture of distinct texels on
// `slot` (none: untextured), seen by a 16 x 16 view.
Scene quad(int slot) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f, 0.4f, 0.3f));
  test::add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, m);
  for (size_t i = 0; i < s.positions.size(); ++i)
    s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, (s.positions[i].y + 2.0f) / 4.0f);
  if (slot >= 0) {
    Texture t;
    t.width = 4;
    t.height = 1;
    t.rgba8 = {10, 200, 30, 255, 250, 20, 90, 255, 60, 120, 240, 255, 180, 180, 10, 255};
    s.textures.push_back(t);
    TextureRef* refs[kTextureSlots] = {&s.materials[m].base_color_texture, &s.materials[m].metallic_roughness_texture,
                                       &s.materials[m].normal_texture, &s.materials[m].emissive_texture};
    refs[slot]->texture = 0;
    refs[slot]->transform.scale = vec2(7.0f, 1.0f);
  }
  test::front_camera(s, vec3(0.0f), 1.0f, 0.5f);
  s.volume = fit_volume(s.bounds);
  return s;
}

TEST(FreedomShortcuts, AnUntexturedMaterialIsTheSameAtEveryLod) {
  const Scene s = quad(-1);
  ASSERT_FALSE(material_reads_lods(s.materials[0]));
  ASSERT_FALSE(material_reads_srgb_order(s.materials[0]));
  const SurfacePoint p = interpolate_surface(s, 0, 0.3f, 0.2f);
  const SurfaceMaterial exact = evaluate_material(s, p);
  EXPECT_TRUE(same_material(evaluate_material(s, p, other_lods(false)), exact));
  EXPECT_TRUE(same_material(evaluate_material(s, p, other_lods(true)), exact));
}

TEST(FreedomShortcuts, OnlyAnSrgbTextureReadsTheDecodeOrder) {
  // A linear texture (metallic-roughness): decoded before or after filtering, the same bits.
  const Scene linear = quad(kSlotMetallicRoughness);
  ASSERT_TRUE(material_reads_lods(linear.materials[0]));
  ASSERT_FALSE(material_reads_srgb_order(linear.materials[0]));
  // The base colour (sRGB): the order moves a blend of two texels (GL 4.5 §8.24), so the
  // predicate must say so, or the slacks would leave a real alternative out.
  const Scene srgb = quad(kSlotBaseColor);
  ASSERT_TRUE(material_reads_srgb_order(srgb.materials[0]));
  bool order_moved_srgb = false;
  for (float b1 = 0.05f; b1 < 1.0f; b1 += 0.1f) {
    SlotLods before, after;
    after.srgb_after_filter = true;
    const SurfacePoint lp = interpolate_surface(linear, 0, b1, 0.1f);
    EXPECT_TRUE(same_material(evaluate_material(linear, lp, before), evaluate_material(linear, lp, after)));
    const SurfacePoint sp = interpolate_surface(srgb, 0, b1, 0.1f);
    order_moved_srgb = order_moved_srgb ||
                       !same_material(evaluate_material(srgb, sp, before), evaluate_material(srgb, sp, after));
  }
  EXPECT_TRUE(order_moved_srgb);
}

TEST(FreedomShortcuts, PositionsAreThoseOfTheShiftedSurfacePoints) {
  const Scene s = quad(-1);
  const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  const VisibilityBuffer vb = render_visibility(s.positions, s.triangles, vp, 16, 16);
  const WindowBarycentrics wb(vp, 16, 16);
  int checked = 0;
  for (int row = 0; row < 16; ++row)
    for (int x = 0; x < 16; ++x) {
      const size_t i = vb.index(x, row);
      ASSERT_GE(vb.triangle[i], 0);
      SurfacePoint points[kSlackShifts];
      vec3 positions[kSlackShifts];
      const uint32_t tri = uint32_t(vb.triangle[i]);
      const int n = shifted_surface_points(s, wb, x, row, tri, vb.bary[i], points);
      ASSERT_EQ(shifted_surface_positions(s, wb, x, row, tri, vb.bary[i], positions), n);
      for (int k = 0; k < n; ++k, ++checked) EXPECT_TRUE(same_bits(positions[k], points[k].position));
    }
  EXPECT_EQ(checked, 16 * 16 * kSlackShifts);
}

TEST(FreedomShortcuts, PixelMaterialWithoutLodsWhereNoneAreRead) {
  for (const int slot : {-1, int(kSlotBaseColor), int(kSlotNormal)}) {
    const Scene s = quad(slot);
    const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
    const VisibilityBuffer vb = render_visibility(s.positions, s.triangles, vp, 16, 16);
    for (int row = 0; row < 16; row += 3)
      for (int x = 0; x < 16; x += 3) {
        const size_t i = vb.index(x, row);
        const uint32_t tri = uint32_t(vb.triangle[i]);
        const PixelMaterial full = pixel_material(s, vp, 16, 16, x, row, tri, vb.bary[i]);
        const PixelMaterial quick = pixel_material_lods_if_read(s, vp, 16, 16, x, row, tri, vb.bary[i]);
        EXPECT_TRUE(same_material(quick.material, full.material)) << "slot " << slot;
        if (slot >= 0)  // a textured material keeps its lods (the texture slack's candidates)
          EXPECT_EQ(quick.lods.exact.lambda[slot], full.lods.exact.lambda[slot]);
      }
  }
}

TEST(FreedomShortcuts, TapsWithoutAVectorAreTapPositions) {
  VctSettings oracle;  // the 3x3 square
  std::vector<vec2> seen;
  EXPECT_EQ(for_each_tap(10.25f, 3.5f, oracle, 64, 1.0f, [&](const vec2& t) { seen.push_back(t); }), 9);
  EXPECT_EQ(seen, tap_positions(10.25f, 3.5f, oracle, 64, 1.0f));
  EXPECT_EQ(seen.front(), vec2(9.25f, 2.5f));
  VctSettings engine;
  engine.pcf_taps = "-0.001,0.002 0.003,-0.004";
  engine.pcf_tap_unit = PcfTapUnit::Uv;
  engine.pcf_tap_scale = PcfTapScale::InvW;
  seen.clear();
  EXPECT_EQ(for_each_tap(100.0f, 50.0f, engine, 2048, 0.5f, [&](const vec2& t) { seen.push_back(t); }), 2);
  EXPECT_EQ(seen, tap_positions(100.0f, 50.0f, engine, 2048, 0.5f));
  EXPECT_EQ(seen[0], vec2(100.0f + -0.001f * 2048.0f / 0.5f, 50.0f + 0.002f * 2048.0f / 0.5f));
  EXPECT_EQ(pcf_reach(oracle), vec2(1.5f));  // |offset| 1 + half a texel (nearest)
}

bool same_buffer(const VisibilityBuffer& a, const VisibilityBuffer& b) {
  return a.width == b.width && a.height == b.height && a.triangle == b.triangle && a.front_facing == b.front_facing &&
         a.facing_tie == b.facing_tie && std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)) == 0 &&
         std::memcmp(a.bary.data(), b.bary.data(), a.bary.size() * sizeof(vec3)) == 0;
}

TEST(FreedomShortcuts, OnePassVisibilityAndDepthTiesAreTheTwoCalls) {
  // A quad, its coplanar twin (tied everywhere) and a third crossing both: one and two ties a pixel.
  Scene s = quad(-1);
  const uint32_t m = s.triangle_material[0];
  test::add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, m);
  test::add_quad(s, {-2, -2, -2.5f}, {2, -2, -2.5f}, {2, 2, -1.5f}, {-2, 2, -1.5f}, {0, -0.7f, 0.7f}, m);
  const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  const vec2 sample(0.5f + 1.0f / 256.0f, 0.5f - 1.0f / 256.0f);
  std::vector<VisibilityBuffer> tied;
  const VisibilityBuffer vb = visibility_and_depth_ties(s, vp, 16, 16, sample, tied);
  const VisibilityBuffer want = render_visibility(s.positions, s.triangles, vp, 16, 16, &s, sample);
  const std::vector<VisibilityBuffer> want_tied = depth_tied_surfaces(s, vp, want, sample);
  EXPECT_TRUE(same_buffer(vb, want));
  ASSERT_EQ(tied.size(), want_tied.size());
  ASSERT_GE(tied.size(), 1u);  // the twin ties at every pixel
  for (size_t k = 0; k < tied.size(); ++k) EXPECT_TRUE(same_buffer(tied[k], want_tied[k])) << "layer " << k;
}

}  // namespace
}  // namespace vct
