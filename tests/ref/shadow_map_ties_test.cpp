// Raster alternatives in light space (freedoms/shadow_map_ties.h): the depths a correct GL may store
// at a shadow-map texel under 2^-8 texel vertex snapping and alpha-test ties, hand-computed on
// orthographic maps where one texel is one world unit and every window depth is exact.
#include <cmath>
#include <gtest/gtest.h>

#include "alpha_card_scene.h"
#include "scene/gltf_loader.h"
#include "freedoms/plane_setup.h"
#include "freedoms/raster_alternatives.h"
#include "freedoms/shadow_map_ties.h"
#include "stage_test_scene.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

constexpr int kSize = 16;

// Looks down -z from the origin; x, y in [-8, 8] map onto 16 x 16 texels (texel column c's centre
// at x = c - 7.5), depth 1..11: window depth (-z - 1) / 10, so z = -3 stores 0.2 and z = -8 0.7.
mat4 light_view_proj() {
  return glm::ortho(-8.0f, 8.0f, -8.0f, 8.0f, 1.0f, 11.0f) *
         glm::lookAt(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 1.0f, 0.0f));
}

float lo_of(const Image& r, int x, int row) { return r.at(x, row, 0); }
float hi_of(const Image& r, int x, int row) { return r.at(x, row, 1); }

TEST(ShadowMapTies, SilhouetteThroughAColumnOfTexelCentresAdmitsTheFarDepthAndTheClearValue) {
  Scene s;
  const uint32_t grey = test::add_material(s, vec3(0.5f));
  // A quad at z = -3 whose right edge x = 2.5 runs through the centres of texel column 10; behind
  // it, in the lower half of the map only (y < 0: image rows 8..15), a wall at z = -8.
  test::add_quad(s, {-9, -9, -3}, {2.5f, -9, -3}, {2.5f, 9, -3}, {-9, 9, -3}, {0, 0, 1}, grey);
  test::add_quad(s, {-9, -9, -8}, {9, -9, -8}, {9, 0, -8}, {-9, 0, -8}, {0, 0, 1}, grey);
  const Image r = shadow_depth_range(s, light_view_proj(), kSize, ShadowDepthFormat::Depth32f);
  ASSERT_EQ(r.channels, 2);
  EXPECT_EQ(r.channel_names[0], "depth.0.lo");
  EXPECT_EQ(r.channel_names[1], "depth.0.hi");
  // Both planes face the light head-on: their margin is the float term alone.
  const float m = float(std::ldexp(1.0, -22));
  for (int row = 0; row < kSize; ++row) {
    const bool wall = row >= 8;
    // On the edge: the reference keeps the wall (0.7) or nothing (1) -- the top-left rule leaves a
    // centre on a right edge uncovered -- and the sample one step left lands on the quad (0.2, its
    // depth at the centre, less its plane's margin: a snapped plane moves in every world).
    EXPECT_NEAR(lo_of(r, 10, row), 0.2f - m, 1e-7f) << row;
    EXPECT_NEAR(hi_of(r, 10, row), wall ? 0.7f + m : 1.0f, 1e-7f) << row;
    // Half a texel off the edge (128 sub-texel steps): only the own plane's margin.
    EXPECT_NEAR(lo_of(r, 9, row), 0.2f - m, 1e-7f) << row;
    EXPECT_NEAR(hi_of(r, 9, row), 0.2f + m, 1e-7f) << row;
    EXPECT_NEAR(lo_of(r, 11, row), wall ? 0.7f - m : 1.0f, 1e-7f) << row;
    EXPECT_NEAR(hi_of(r, 11, row), wall ? 0.7f + m : 1.0f, 1e-7f) << row;
    EXPECT_NEAR(hi_of(r, 3, row) - lo_of(r, 3, row), 2.0f * m, 1e-7f) << row;
  }
  // Nothing covers any sample of the upper right: the clear value only.
  EXPECT_EQ(lo_of(r, 14, 2), 1.0f);
  EXPECT_EQ(hi_of(r, 14, 2), 1.0f);
}

TEST(ShadowMapTies, SlopedPlaneSpansItsOwnMarginOfOneStepPerAxis) {
  Scene s;
  const uint32_t grey = test::add_material(s, vec3(0.5f));
  // z = -3 - 0.1 x: window depth 0.2 + 0.01 x, 0.01 per texel along x, none along y; one
  // sub-texel step on each axis moves it by 2^-8 * 0.01 (depth_tie_margin), times the plane's
  // extrapolation factor, plus the arithmetic: 2^-22, or the plane's float set-up where larger
  // (plane_setup.h; a few 2^-24 here).
  test::add_quad(s, {-9, -9, -2.1f}, {9, -9, -3.9f}, {9, 9, -3.9f}, {-9, 9, -2.1f}, {0, 0, 1}, grey);
  const Image r = shadow_depth_range(s, light_view_proj(), kSize, ShadowDepthFormat::Depth32f);
  double setup = 0.0;
  for (const RasterTriangle& t : setup_and_bin(s.positions, s.triangles, light_view_proj(), kSize, kSize).triangles) {
    setup = std::max(setup, plane_setup_margin(t));
    // Both halves: legs L = 18 texels = 4608 steps, A = L^2, R = 2L + 2L + 8 (perimeter + 8); the
    // reaches over the box grown by a step are 3L + 8 (each leg) and 2L + 8 (the diagonal), so the
    // factor is 1 + 4 (8L + 24) / (L^2 - 4L - 8) = 1.0069551.
    EXPECT_NEAR(depth_plane_extrapolation_factor(t), 1.0069551, 1e-7);
  }
  ASSERT_LT(setup, 2e-6);
  const double m = std::max(std::ldexp(1.0, -22), setup + 2.0 * kFloatRoundoff) + 1.0069551 * 0.01 / 256.0;
  for (int row = 1; row < kSize - 1; row += 3)
    for (int x = 1; x < kSize - 1; x += 2) {
      const double z = 0.2 + 0.01 * (double(x) - 7.5);
      EXPECT_NEAR(lo_of(r, x, row), z - m, 2e-7) << x << "," << row;
      EXPECT_NEAR(hi_of(r, x, row), z + m, 2e-7) << x << "," << row;
    }
}

TEST(ShadowMapTies, AlphaTestAtTheCutoffAdmitsTheCardAndTheBackdrop) {
  // The half-masked card (alpha_card_scene.h, alpha = cutoff on x = 0) seen by an orthographic
  // light from z = 1 over exactly the card, 33 texels: x = 0 is column 16's centres. Window depth
  // (-z_view - 0.5) / 2.5: the card (z_view = -1) stores 0.2, the backdrop (-2) 0.6.
  const Scene s = test::half_masked_card(true);
  const mat4 vp = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.5f, 3.0f) *
                  glm::lookAt(vec3(0.0f, 0.0f, 1.0f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f));
  const Image r = shadow_depth_range(s, vp, 33, ShadowDepthFormat::Depth32f);
  for (int row = 8; row <= 24; ++row) {
    EXPECT_LE(lo_of(r, 16, row), 0.2f + 1e-6f) << row;
    EXPECT_GE(hi_of(r, 16, row), 0.6f - 1e-6f) << row;
    // Two columns away the alpha is 0.12 from the cutoff: one outcome, the own plane's margin.
    EXPECT_NEAR(lo_of(r, 18, row), 0.2f, 1e-6f) << row;
    EXPECT_NEAR(hi_of(r, 18, row), 0.2f, 1e-6f) << row;
    EXPECT_NEAR(lo_of(r, 14, row), 0.6f, 1e-6f) << row;
    EXPECT_NEAR(hi_of(r, 14, row), 0.6f, 1e-6f) << row;
  }
}

TEST(ShadowMapTies, ACardCutAwayForCertainDoesNotHideTheTieBehindIt) {
  // The same card and backdrop under a fully transparent masked card (alpha 0 everywhere: cut away
  // for certain), the light at z = 2: window depth (-z_view - 0.5) / 3, so the clear card stores
  // nothing, the half-masked card 0.5, the backdrop 5/6. The tie on x = 0 is the second layer's.
  Scene s = test::half_masked_card(true);
  Material clear = s.materials[0];
  clear.base_color_texture.texture = -1;
  clear.base_color_factor = vec4(1.0f, 1.0f, 1.0f, 0.0f);
  s.materials.push_back(clear);
  test::add_card_quad(s, 0.5f, 1.0f, uint32_t(s.materials.size() - 1));
  const mat4 vp = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.5f, 3.5f) *
                  glm::lookAt(vec3(0.0f, 0.0f, 2.0f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f));
  const Image r = shadow_depth_range(s, vp, 33, ShadowDepthFormat::Depth32f);
  for (int row = 8; row <= 24; ++row) {
    EXPECT_LE(lo_of(r, 16, row), 0.5f + 1e-6f) << row;
    EXPECT_GE(hi_of(r, 16, row), 5.0f / 6.0f - 1e-6f) << row;
    EXPECT_NEAR(hi_of(r, 18, row) - lo_of(r, 18, row), 0.0f, 1e-6f) << row;
  }
}

TEST(ShadowMapTies, TwoFlipsInARowReachTheClearValue) {
  // Two half-masked cards, no backdrop (scenes/regressions/seed-207: a masked fold under a sun):
  // on x = 0 both alphas are at the cutoff, so a correct GL may keep the front card (window depth
  // 1/3 with the light at z = 2), cut it and keep the back one (1/2), or cut both and store the
  // clear value. The surface behind the first flip is not the deepest outcome when it may flip too.
  Scene s = test::half_masked_card(false);
  test::add_card_quad(s, 0.5f, 1.0f, 0);
  const mat4 vp = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.5f, 3.5f) *
                  glm::lookAt(vec3(0.0f, 0.0f, 2.0f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f));
  const Image r = shadow_depth_range(s, vp, 33, ShadowDepthFormat::Depth32f);
  for (int row = 8; row <= 24; ++row) {
    EXPECT_LE(lo_of(r, 16, row), 1.0f / 3.0f + 1e-6f) << row;
    EXPECT_EQ(hi_of(r, 16, row), 1.0f) << row;
    // Two columns right both alphas are 0.12 above the cutoff: the front card for certain.
    EXPECT_NEAR(lo_of(r, 18, row), 1.0f / 3.0f, 1e-6f) << row;
    EXPECT_NEAR(hi_of(r, 18, row), 1.0f / 3.0f, 1e-6f) << row;
  }
}

TEST(ShadowMapTies, ASliverThinnerThanTwoStepsMayCoverACentreNoCommonShiftCovers) {
  // scenes/regressions/seed-43-medium: one needle triangle seen by a point light's cube face 3.
  // At texel (22, row 119) (centre (22.5, 8.5) in window texels) its two edges pass 0.003 texel
  // either side of x = 22.497, so the centre lies outside by less than one step while a common
  // shift by (+-2^-8, +-2^-8) jumps over the needle; snapping each vertex on its own may cover it.
  // Mesa llvmpipe stored 0.96112 there; the reference stores the clear value.
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-43-medium/scene.gltf");
  VctSettings settings;
  settings.shadow_map_size = 128;
  std::vector<ShadowMap> maps = render_shadow_maps(s, settings);
  ASSERT_EQ(maps.size(), 1u);
  ASSERT_TRUE(maps[0].is_cube());
  const Image r = shadow_depth_range(s, maps[0].cube_view_proj[3], 128, ShadowDepthFormat::Depth32f);
  EXPECT_LE(lo_of(r, 22, 119), 0.96112f);
  EXPECT_EQ(hi_of(r, 22, 119), 1.0f);
  // Two texels off the needle nothing may cover the centre.
  EXPECT_EQ(lo_of(r, 20, 119), 1.0f);
  EXPECT_EQ(lo_of(r, 24, 119), 1.0f);
}

TEST(ShadowMapTies, AnAlphaFlipsPlaneCarriesItsSnapMargin) {
  // scenes/regressions/seed-482-small: a masked fold under a sun; at texel (19, row 17) the
  // reference cuts a 0.1-texel-wide sliver whose alpha may flip. Its plane tilts far across its
  // width, so one snap step moves its depth at the centre by ~2e-4: Mesa llvmpipe stored 0.57960
  // against the plane's 0.57981. The flip's outcome is a range (its depth -+ its plane's margin),
  // as every fragment's in the sweep.
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-482-small/scene.gltf");
  VctSettings settings;
  settings.shadow_map_size = 64;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, settings);
  ASSERT_EQ(maps.size(), 1u);
  const Image r = shadow_depth_range(s, maps[0].view_proj, 64, ShadowDepthFormat::Depth32f);
  EXPECT_LE(lo_of(r, 19, 17), 0.57960f);
  // A margin, not the whole map: 2^-8 (|dz/dx| + |dz/dy|) per step of a plane that tilts 0.037 in
  // depth across a 0.1-texel width is 2.1e-3 here, about twice that with the sliver's extrapolation
  // factor (tests/ref/plane_snap_test.cpp), and the same sliver's float plane set-up (plane_setup.h)
  // about 2.1e-3 again: 6.4e-3 below the plane's value.
  EXPECT_GE(lo_of(r, 19, 17), 0.5730f);
  EXPECT_EQ(hi_of(r, 19, 17), 1.0f);     // the reference's own (cut: the clear value)
}

// A masked quad at z = -3 (window depth 0.2, nothing behind it) whose base colour is a 2 x 1
// NEAREST, REPEAT texture of alpha 1 and 0 (cutoff 1/2), with u = k x + 1/4: in texel units
// 2 k x + 1/2, so every texel centre of the map (x = c - 7.5) lies in the middle of an opaque
// texel, and the snap square (+-2^-8 texel) reaches +-k/128 texels of the texture.
Scene striped_mask(float k) {
  Scene s;
  Texture t = test::two_texel_texture("stripes", {255, 255, 255, 255, 255, 255, 255, 0}, true);
  t.wrap_s = t.wrap_t = Wrap::Repeat;
  s.textures.push_back(t);
  const uint32_t m = test::add_material(s, vec3(0.5f));
  s.materials[m].base_color_texture.texture = 0;
  s.materials[m].alpha_mode = AlphaMode::Mask;
  s.materials[m].alpha_cutoff = 0.5f;
  test::add_quad(s, {-9, -9, -3}, {9, -9, -3}, {9, 9, -3}, {-9, 9, -3}, {0, 0, 1}, m);
  for (size_t i = 0; i < s.positions.size(); ++i) s.uv0[i] = vec2(k * s.positions[i].x + 0.25f, 0.5f);
  return s;
}

TEST(ShadowMapTies, AnAlphaTexelInsideTheSnapSquareMayFlipWhereNoCornerDoes) {
  // k = 256: the square reaches +-2 texels, so its corners land on opaque texels (as the centre)
  // while the transparent ones between them lie inside it: GL's sample may land there (each vertex
  // snaps on its own; at a covered centre the point interpolated moves anywhere in the square), so
  // the clear value joins the range. The four corners alone never flip here
  // (scenes/regressions/seed-2289-small: a noise-masked wall seen edge-on from a point light).
  const Image wide = shadow_depth_range(striped_mask(256.0f), light_view_proj(), kSize, ShadowDepthFormat::Depth32f);
  // k = 16: the square reaches +-1/8 texel, inside one opaque texel: the quad for certain.
  const Image narrow = shadow_depth_range(striped_mask(16.0f), light_view_proj(), kSize, ShadowDepthFormat::Depth32f);
  const float m = float(std::ldexp(1.0, -22));
  for (int row = 1; row < kSize - 1; row += 2)
    for (int x = 1; x < kSize - 1; x += 3) {
      EXPECT_NEAR(lo_of(wide, x, row), 0.2f - m, 1e-7f) << x << "," << row;
      EXPECT_EQ(hi_of(wide, x, row), 1.0f) << x << "," << row;
      EXPECT_NEAR(lo_of(narrow, x, row), 0.2f - m, 1e-7f) << x << "," << row;
      EXPECT_NEAR(hi_of(narrow, x, row), 0.2f + m, 1e-7f) << x << "," << row;
    }
}

TEST(ShadowMapTies, AMaskedWallSeenEdgeOnMayFlipAnywhereInItsSnapSquare) {
  // scenes/regressions/seed-2289-small: one wall triangle, alpha-masked by a NEAREST noise texture,
  // seen nearly edge-on by a point light's cube face 4; along texel column 128 one 2^-8 texel step
  // crosses several of its texels. Mesa llvmpipe kept the wall (0.89305) at rows 231 and 244, where
  // the reference's sample and the square's four corners all lie on transparent texels, and cut it
  // (the clear value) at row 251, where they all lie on opaque ones.
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-2289-small/scene.gltf");
  VctSettings settings;
  settings.shadow_map_size = 256;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, settings);
  ASSERT_EQ(maps.size(), 1u);
  ASSERT_TRUE(maps[0].is_cube());
  const Image r = shadow_depth_range(s, maps[0].cube_view_proj[4], 256, ShadowDepthFormat::Depth32f);
  for (int row : {231, 244}) {
    EXPECT_LE(lo_of(r, 128, row), 0.89305f) << row;
    EXPECT_EQ(hi_of(r, 128, row), 1.0f) << row;
  }
  EXPECT_LE(lo_of(r, 128, 251), 0.89265f);
  EXPECT_EQ(hi_of(r, 128, 251), 1.0f);
  // One column right the wall covers no centre (the clear value for certain).
  EXPECT_EQ(lo_of(r, 130, 244), 1.0f);
}

TEST(ShadowMapTies, CubeFacesGetRangesHoldingTheirUnormMap) {
  Scene s = test::stage_room();
  s.lights.resize(1);
  s.lights[0].kind = LightKind::Point;
  VctSettings st;
  st.shadow_map_size = 32;
  st.shadow_depth_format = ShadowDepthFormat::Depth16;
  std::vector<ShadowMap> maps = render_shadow_maps(s, st);
  add_shadow_tie_ranges(s, st, maps);
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_TRUE(maps[0].tie_range.empty());  // a point light has faces, no 2D map
  const double q = 1.0 / 65535.0;
  const auto on_grid = [](float z) { return stored_window_depth(z, ShadowDepthFormat::Depth16) == z; };
  int widened = 0;
  for (size_t f = 0; f < 6; ++f) {
    const Image& face = maps[0].cube[f];
    const Image& r = maps[0].cube_tie_range[f];
    ASSERT_EQ(r.width, 32);
    ASSERT_EQ(r.channels, 2);
    for (int row = 0; row < 32; ++row)
      for (int x = 0; x < 32; ++x) {
        const float z = face.at(x, row, 0), lo = lo_of(r, x, row), hi = hi_of(r, x, row);
        EXPECT_LE(lo, z);
        EXPECT_GE(hi, z);
        // Both ends rounded to the format's steps, as the map.
        EXPECT_TRUE(on_grid(lo)) << lo;
        EXPECT_TRUE(on_grid(hi)) << hi;
        widened += double(hi - lo) > 1.5 * q;
      }
  }
  EXPECT_GT(widened, 0);  // the room's box and walls have silhouettes in some face
}

}  // namespace
}  // namespace vct
