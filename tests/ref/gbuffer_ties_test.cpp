// Raster alternatives (freedoms/gbuffer_ties.h): the values a correct GL may show at a G-buffer
// pixel when an edge or a triangle's facing ties under 2^-8 pixel vertex snapping.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "alpha_card_scene.h"
#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/gbuffer_ties.h"
#include "stage_test_scene.h"
#include "stages/gbuffer.h"
#include "stages/raster.h"

namespace vct {
namespace {

int64_t area2_of(const int64_t x[3], const int64_t y[3]) {
  return (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
}

// Brute force: does moving each of the six coordinates by -1, 0 or +1 change the area's sign?
bool some_snap_flips(const int64_t x[3], const int64_t y[3]) {
  const int64_t a = area2_of(x, y);
  for (int code = 0; code < 729; ++code) {
    int64_t px[3], py[3];
    int c = code;
    for (int i = 0; i < 3; ++i) {
      px[i] = x[i] + (c % 3) - 1, c /= 3;
      py[i] = y[i] + (c % 3) - 1, c /= 3;
    }
    const int64_t b = area2_of(px, py);
    if ((a > 0) != (b > 0) || b == 0) return true;
  }
  return false;
}

TEST(RasterTies, FacingMayFlipHoldsEveryOneStepSnapThatFlips) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-40, 40);
  int flips = 0, flagged = 0;
  for (int n = 0; n < 4000; ++n) {
    int64_t x[3], y[3];
    for (int i = 0; i < 3; ++i) x[i] = coord(rng), y[i] = coord(rng);
    const int64_t a = area2_of(x, y);
    if (a == 0) continue;  // degenerate after snapping: no fragments
    const bool flips_here = some_snap_flips(x, y);
    const bool flag = facing_may_flip(x, y, a);
    if (flips_here) {
      EXPECT_TRUE(flag) << x[0] << "," << y[0] << " " << x[1] << "," << y[1] << " " << x[2] << "," << y[2];
    }
    flips += flips_here;
    flagged += flag;
  }
  EXPECT_GT(flips, 20);  // the sample holds slivers, so the check above is exercised
  EXPECT_LT(flagged, 1000);  // and most triangles keep their facing
}

TEST(RasterTies, FacingMayFlipIsTheAreaAgainstThePerimeterPlusEight) {
  // (0,0) (10,0) (0,10): P = 10 + 20 + 10 = 40; the bound is |area2| <= 48.
  const int64_t x[3] = {0, 10, 0}, y[3] = {0, 0, 10};
  EXPECT_FALSE(facing_may_flip(x, y, 100));  // the triangle's own area
  EXPECT_TRUE(facing_may_flip(x, y, 48));
  EXPECT_FALSE(facing_may_flip(x, y, 49));
  EXPECT_TRUE(facing_may_flip(x, y, -48));
}

// Camera at the origin looking down -z, yfov 1, 16 x 12 pixels: one pixel is 2 tan(0.5) * d / 12
// world units at depth d on both axes.
constexpr int kW = 16, kH = 12;
float pixel_world(float depth) { return 2.0f * std::tan(0.5f) * depth / float(kH); }
// World x (at depth d) of the centre of pixel column `col`, and y of window row `wy` (y up).
float column_x(int col, float depth) { return (float(col) + 0.5f - 0.5f * kW) * pixel_world(depth); }
float window_row_y(float wy, float depth) { return (wy - 0.5f * kH) * pixel_world(depth); }

Scene camera_scene() {
  Scene s;
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
  return s;
}

int channel(const Image& im, const std::string& name) {
  for (size_t c = 0; c < im.channel_names.size(); ++c)
    if (im.channel_names[c] == name) return int(c);
  return -1;
}

GBuffer render(Scene& s) {
  s.volume = fit_volume(s.bounds);
  VctSettings st;
  st.width = kW;
  st.height = kH;
  return render_gbuffer_with_freedoms(s, st);
}

TEST(RasterTies, SilhouetteThroughAPixelCentreAdmitsTheSurfaceBehind) {
  Scene s = camera_scene();
  const uint32_t blue = test::add_material(s, vec3(0.1f, 0.2f, 0.9f));
  const uint32_t red = test::add_material(s, vec3(0.9f, 0.1f, 0.1f));
  // Front quad at z = -2 whose right edge runs through the centres of pixel column 10; a red wall
  // at z = -4 behind everything.
  const float edge = column_x(10, 2.0f);
  test::add_quad(s, {-3, -3, -2}, {edge, -3, -2}, {edge, 3, -2}, {-3, 3, -2}, {0, 0, 1}, blue);
  test::add_quad(s, {-9, -9, -4}, {9, -9, -4}, {9, 9, -4}, {-9, 9, -4}, {0, 0, 1}, red);
  const GBuffer g = render(s);
  ASSERT_EQ(g.tie_range.channels, 42);  // 21 G-buffer values, lo and hi
  const int r_lo = channel(g.tie_range, "albedo.0.lo"), r_hi = channel(g.tie_range, "albedo.0.hi");
  const int z_lo = channel(g.tie_range, "position.2.lo"), z_hi = channel(g.tie_range, "position.2.hi");
  ASSERT_GE(r_lo, 0);
  ASSERT_GE(z_hi, 0);
  for (int row = 1; row < kH - 1; ++row) {
    // On the edge: the red wall's values (albedo 0.9, z = -4) and the blue quad's (0.1, z = -2)
    // are both admissible, whichever the reference shows.
    EXPECT_FLOAT_EQ(g.tie_range.at(10, row, r_lo), 0.1f) << row;
    EXPECT_FLOAT_EQ(g.tie_range.at(10, row, r_hi), 0.9f) << row;
    EXPECT_NEAR(g.tie_range.at(10, row, z_lo), -4.0f, 1e-4f) << row;
    EXPECT_NEAR(g.tie_range.at(10, row, z_hi), -2.0f, 1e-4f) << row;
    // One column off the edge (half a pixel from it, 128 sub-pixel steps): only the quads' own
    // diagonals may be crossed there, which show the same plane and material (float rounding);
    // the position spans its own plane at the (+-2^-8, +-2^-8) shifts: 2 x 2^-8 pixel in x and y
    // (the quad at depth 2 left of the edge, the wall at depth 4 right of it).
    const int x_lo = channel(g.tie_range, "position.0.lo"), y_lo = channel(g.tie_range, "position.1.lo");
    for (int x : {5, 9, 11})
      for (int c = 0; c < g.tie_range.channels; c += 2) {
        const float shift_span = 2.0f * pixel_world(x < 10 ? 2.0f : 4.0f) / 256.0f;
        const float span = g.tie_range.at(x, row, c + 1) - g.tie_range.at(x, row, c);
        const float expected = c == x_lo || c == y_lo ? shift_span : 0.0f;
        EXPECT_NEAR(span, expected, 1e-5f) << x << "," << row << " " << c;
      }
  }
}

// A wall receding to the right (z = -2 at x = -3, z = -6 at x = 3): at interior pixels the depth
// spans its own plane at the (+-2^-8, +-2^-8) sample shifts, 2^-8 (|dz/dx| + |dz/dy|) either side
// (dz/dy = 0 here; dz/dx from the reference's own neighbours), as the position does. Without it a
// pixel whose neighbours are other surfaces, so that the depth model's slope term misses the
// plane's, fails on its own snap (hunt seeds 413, 579: 1.5e-4 beyond, the position admitted).
TEST(RasterTies, DepthSpansItsOwnPlaneAtTheShifts) {
  Scene s = camera_scene();
  const uint32_t grey = test::add_material(s, vec3(0.5f));
  test::add_quad(s, {-3, -3, -2}, {3, -3, -6}, {3, 3, -6}, {-3, 3, -2}, {0.8944f, 0, 0.4472f}, grey);
  const GBuffer g = render(s);
  const int lo = channel(g.tie_range, "depth.0.lo"), hi = channel(g.tie_range, "depth.0.hi");
  ASSERT_GE(lo, 0);
  int checked = 0;
  for (int row = 2; row < kH - 2; ++row)
    for (int x = 3; x < kW - 3; ++x) {
      // Only where the wall covers both neighbours (it ends inside the image on the right).
      if (g.coverage.at(x - 1, row, 0) == 0.0f || g.coverage.at(x + 1, row, 0) == 0.0f || g.depth.at(x + 1, row, 0) >= 1.0f)
        continue;
      const float dzdx = 0.5f * (g.depth.at(x + 1, row, 0) - g.depth.at(x - 1, row, 0));
      const float m = std::abs(dzdx) / 256.0f;
      ASSERT_GT(m, 1e-6f);
      ++checked;
      EXPECT_NEAR(g.tie_range.at(x, row, lo), g.depth.at(x, row, 0) - m, 0.05f * m) << x << "," << row;
      EXPECT_NEAR(g.tie_range.at(x, row, hi), g.depth.at(x, row, 0) + m, 0.05f * m) << x << "," << row;
    }
  EXPECT_GT(checked, 40);
}

// An alternative carries its own plane under the snap, as the front surface does (issue 34 kind
// 2: GL's point on a nearly edge-on triangle far along the view ray). A front quad at z = -1 whose
// left edge runs through the centres of pixel column 10; behind it a tall quad nearly containing
// the centre rays of that column: its plane x = k d + e (d - 3), d = -z, k the centre ray's slope
// x / d and e = 2^-3 pixel at unit depth, spans 23 sub-pixel steps around the column and is hit
// by the centre ray at d = 3. The -x shifted sample leaves the front quad and finds it; moved by
// one step (2^-8 pixel, slope k -+ 2^-8 pixel) the ray meets its plane at d = 3e / (e +- 2^-8) =
// 96/33 .. 96/31: the position GL may show there spans that, not only d = 3. (The reference's own
// raster snaps the sliver's vertices too, so its centre value is its snapped plane's, within a
// few hundredths of d = 3, and the range's far end 3.12.)
TEST(RasterTies, AnAlternativesPositionSpansItsOwnPlaneUnderTheSnap) {
  Scene s = camera_scene();
  const uint32_t grey = test::add_material(s, vec3(0.5f));
  const uint32_t green = test::add_material(s, vec3(0.1f, 0.8f, 0.1f));
  const float edge = column_x(10, 1.0f);
  test::add_quad(s, {edge, -3, -1}, {3, -3, -1}, {3, 3, -1}, {edge, 3, -1}, {0, 0, 1}, grey);
  const float k = column_x(10, 1.0f), e = pixel_world(1.0f) / 8.0f;
  const auto at = [&](float d, float y) { return vec3(k * d + e * (d - 3.0f), y, -d); };
  test::add_quad(s, at(2.0f, -3), at(2.0f, 3), at(3.9f, 3), at(3.9f, -3), glm::normalize(vec3(1, 0, k + e)), green);
  const GBuffer g = render(s);
  const int z_lo = channel(g.tie_range, "position.2.lo"), z_hi = channel(g.tie_range, "position.2.hi");
  ASSERT_GE(z_lo, 0);
  int checked = 0;
  for (int row = 2; row < kH - 2; ++row) {
    ASSERT_FLOAT_EQ(g.position.at(10, row, 2), -1.0f) << row;  // the front quad covers the centre
    EXPECT_LT(g.tie_range.at(10, row, z_lo), -3.09f) << row;  // not only its centre, d = 3 +- 0.03
    EXPECT_GT(g.tie_range.at(10, row, z_lo), -3.2f) << row;
    EXPECT_FLOAT_EQ(g.tie_range.at(10, row, z_hi), -1.0f) << row;
    ++checked;
  }
  EXPECT_EQ(checked, kH - 4);
}

// Depth order under a shift (a fold's silhouette, scenes/regressions/fold-29): two faces of a
// fold share an edge through the centres of pixel column 10 and both lie left of it (the front
// face at z = -2, the back face folded behind it to z = -2.5). The centres are on the edge, a
// right edge of both: empty in the reference. The -x shifted samples are covered by both, whose
// planes both contain the edge, so their depths at the centre tie: the snap that moves the edge
// onto the centre may order them either way, and the back face (red) is admissible there too,
// not only the front face (blue) that the shifted visibility keeps.
TEST(RasterTies, FacesTiedInDepthAtAShiftedSampleAreBothAdmitted) {
  Scene s = camera_scene();
  const uint32_t blue = test::add_material(s, vec3(0.1f, 0.2f, 0.9f));
  const uint32_t red = test::add_material(s, vec3(0.9f, 0.1f, 0.1f));
  const float edge = column_x(10, 2.0f);
  const vec3 top(edge, 3, -2), bottom(edge, -3, -2);
  test::add_triangle(s, top, bottom, {-3, 0, -2}, blue);
  test::add_triangle(s, bottom, top, {-3, 0, -2.5f}, red);  // the mesh's winding across the fold
  const GBuffer g = render(s);
  const int r_lo = channel(g.tie_range, "albedo.0.lo"), r_hi = channel(g.tie_range, "albedo.0.hi");
  ASSERT_GE(r_lo, 0);
  for (int row = 3; row < kH - 3; ++row) {
    ASSERT_EQ(g.coverage.at(10, row, 0), 0.0f) << row;  // on the shared right edge: not covered
    EXPECT_FLOAT_EQ(g.tie_range.at(10, row, r_lo), 0.0f) << row;  // empty
    EXPECT_FLOAT_EQ(g.tie_range.at(10, row, r_hi), 0.9f) << row;  // the back face, not only 0.1
    // Two columns left both faces cover the centre and the front face is far in front of the
    // back one there (0.5 m behind at x = -3, a third of that here): no tie, blue only.
    EXPECT_FLOAT_EQ(g.tie_range.at(7, row, r_hi), 0.1f) << row;
  }
}

// A sliver's own snap (hunt seed 6, large class; docs/compare.md "A sliver's own snap"). Window
// sub-pixel coordinates, all on the 2^-8 grid: a blue front triangle A B D and a red needle A B C
// coplanar with it at z = -2, sharing the edge A = (1575, 296), B = (3879, 2596) (nearly 45
// degrees). The needle's apex C = (3186, 1904) lies 0.14 step right of the edge (twice its area
// 468 steps^2); the centre P = (2688, 1408) of pixel (10, window row 5) lies 0.66 step left of it,
// inside the front triangle. Neither P nor any of its (+-1, +-1) step shifts is inside the needle
// (the one shift that crosses the edge lands 0.75 step right of it, where the needle is 0.10 wide),
// but moving C by (-1, +1) step turns the needle over the edge so that it covers P: a GL that
// snaps C the other way shows the red needle there, tied in depth with the blue front. Checked by
// brute force over the 3^6 one-step snaps of the three vertices.
TEST(RasterTies, ASliverThatItsOwnSnapTurnsOverTheCentreIsAdmitted) {
  Scene s = camera_scene();
  const uint32_t blue = test::add_material(s, vec3(0.1f, 0.2f, 0.9f));
  const uint32_t red = test::add_material(s, vec3(0.9f, 0.1f, 0.1f));
  const auto at = [](float sx, float sy) {
    return vec3((sx / 256.0f - 0.5f * kW) * pixel_world(2.0f), window_row_y(sy / 256.0f, 2.0f), -2.0f);
  };
  const vec3 a = at(1575, 296), b = at(3879, 2596), c = at(3186, 1904), d = at(300, 2900);
  test::add_triangle(s, a, b, d, blue);  // counter-clockwise in the window: facing the camera
  test::add_triangle(s, a, c, b, red);
  const GBuffer g = render(s);
  const int r_lo = channel(g.tie_range, "albedo.0.lo"), r_hi = channel(g.tie_range, "albedo.0.hi");
  ASSERT_GE(r_lo, 0);
  const int row = kH - 1 - 5;  // image rows run top down
  ASSERT_FLOAT_EQ(g.albedo.at(10, row, 0), 0.1f);  // the reference shows the front triangle
  EXPECT_FLOAT_EQ(g.tie_range.at(10, row, r_hi), 0.9f);  // and admits the needle
  // A pixel centre well inside the front triangle, 2.8 pixels from the edge: blue only.
  EXPECT_FLOAT_EQ(g.tie_range.at(6, row, r_hi), 0.1f);
}

TEST(RasterTies, NearlyEdgeOnTriangleAdmitsTheNegatedNormal) {
  Scene s = camera_scene();
  const uint32_t grey = test::add_material(s, vec3(0.5f));
  const uint32_t green = test::add_material(s, vec3(0.1f, 0.8f, 0.1f));
  test::add_quad(s, {-9, -9, -4}, {9, -9, -4}, {9, 9, -4}, {-9, 9, -4}, {0, 0, 1}, grey);
  // A sliver at z = -2 two sub-pixel steps high at its right end, along window row 6.5 (the
  // centres of image row 5): twice its window area (~ 1700 x 2 steps^2) is below its L1
  // perimeter (~ 3400 steps) + 8, so one step of snapping on a vertex can turn it over.
  const float step = pixel_world(2.0f) / 256.0f, yc = window_row_y(6.5f, 2.0f);
  test::add_triangle(s, {-0.6f, yc - step, -2}, {0.6f, yc - step, -2}, {0.6f, yc + step, -2}, green);
  const GBuffer g = render(s);
  const int n_lo = channel(g.tie_range, "normal.2.lo"), n_hi = channel(g.tie_range, "normal.2.hi");
  ASSERT_GE(n_lo, 0);
  int sliver_pixels = 0;
  for (int x = 0; x < kW; ++x) {
    if (g.albedo.at(x, 5, 1) != 0.8f) continue;  // not the sliver
    ++sliver_pixels;
    EXPECT_EQ(g.normal.at(x, 5, 2), 1.0f);  // faces the camera
    EXPECT_EQ(g.tie_range.at(x, 5, n_lo), -1.0f) << x;
    EXPECT_EQ(g.tie_range.at(x, 5, n_hi), 1.0f) << x;
  }
  EXPECT_GE(sliver_pixels, 2);
  // The wall two rows down keeps its facing: lo = hi = +1.
  EXPECT_EQ(g.tie_range.at(3, 8, n_lo), 1.0f);
  EXPECT_EQ(g.tie_range.at(3, 8, n_hi), 1.0f);
}

// The flip's other outcome carries its own freedoms, as every alternative (hunt seed 660: a
// masked, textured flip whose albedo lay in its own texture slack). The backdrop behind the card
// gets a 2 x 1 NEAREST texture, black left of x = 0 and white right of it: at the centre column,
// where the card's alpha flips, the backdrop's lookup sits on its texel edge, so its texture slack
// (a 2^-8 pixel shift) reaches the black texel, which its centre lookup alone does not.
TEST(RasterTies, AnAlphaFlipsOtherOutcomeCarriesItsTextureSlack) {
  Scene s = test::half_masked_card(true);
  s.textures.push_back(test::two_texel_texture("black_white", {0, 0, 0, 255, 255, 255, 255, 255}, true));
  s.materials[1].base_color_factor = vec4(1.0f);
  s.materials[1].base_color_texture.texture = int(s.textures.size() - 1);
  VctSettings st;
  st.width = st.height = 33;
  const GBuffer g = render_gbuffer_with_freedoms(s, st);
  const int lo = channel(g.tie_range, "albedo.0.lo"), hi = channel(g.tie_range, "albedo.0.hi");
  ASSERT_GT(g.albedo.at(16, 16, 0), 0.05f);  // the reference keeps the card (alpha = cutoff)
  for (int row = 8; row <= 24; ++row) {
    EXPECT_LT(g.tie_range.at(16, row, lo), 1e-3f) << row;  // the backdrop's black texel
    EXPECT_GT(g.tie_range.at(16, row, hi), 0.99f) << row;  // and its white one
  }
}

}  // namespace
}  // namespace vct

namespace vct {
namespace {

TEST(RasterTies, AlphaTestAtTheCutoffAdmitsBothOutcomes) {
  // The half-masked card (alpha_card_scene.h): alpha = cutoff exactly on x = 0, which an odd
  // image width puts on the centre column's pixel centres; the backdrop (albedo 0.8) behind.
  Scene s = test::half_masked_card(true);
  VctSettings st;
  st.width = st.height = 33;
  const GBuffer g = render_gbuffer_with_freedoms(s, st);
  const int lo = channel(g.tie_range, "albedo.0.lo"), hi = channel(g.tie_range, "albedo.0.hi");
  const float card = g.albedo.at(24, 16, 0), backdrop = g.albedo.at(2, 16, 0);
  ASSERT_NEAR(backdrop, 0.8f, 1e-6f);
  ASSERT_LT(card, 0.5f);  // the card's grey texel, decoded from sRGB
  for (int row = 8; row <= 24; ++row) {
    EXPECT_LE(g.tie_range.at(16, row, lo), card + 1e-5f) << row;  // the same grey texel, filtered
    EXPECT_GE(g.tie_range.at(16, row, hi), backdrop) << row;
    // Two columns away the alpha is 2 pixels' worth from the cutoff: one outcome only.
    EXPECT_EQ(g.tie_range.at(18, row, lo), g.tie_range.at(18, row, hi)) << row;
    EXPECT_EQ(g.tie_range.at(14, row, lo), g.tie_range.at(14, row, hi)) << row;
  }
}

// The half-masked card scenes below, 33 x 33 with every G-buffer freedom.
GBuffer render_cards(Scene& s) {
  s.volume = fit_volume(s.bounds);
  VctSettings st;
  st.width = st.height = 33;
  return render_gbuffer_with_freedoms(s, st);
}

// A chain of two flips (hunt seed 524, scenes/regressions/seed-524-small: both faces of a masked
// thin wall): a second card, the same texture, 0.1 behind the first. On the centre column both
// cards' alpha is at the cutoff, so a correct GL may cut both and show the backdrop; the reference
// keeps the first card. The front-most fragment no GL discards (the backdrop) joins the range, not
// only the two cards. Two columns over both cards pass for certain: the first card only.
TEST(RasterTies, AChainOfAlphaFlipsAdmitsTheFrontMostSurfaceNoGlDiscards) {
  Scene s = test::half_masked_card(true);
  test::add_card_quad(s, -0.1f, 1.0f, 0);
  const GBuffer g = render_cards(s);
  const int lo = channel(g.tie_range, "albedo.0.lo"), hi = channel(g.tie_range, "albedo.0.hi");
  const float card = g.albedo.at(24, 16, 0);
  ASSERT_LT(card, 0.5f);
  for (int row = 10; row <= 22; ++row) {
    ASSERT_FLOAT_EQ(g.albedo.at(16, row, 0), card) << row;  // the reference keeps the first card
    EXPECT_GE(g.tie_range.at(16, row, hi), 0.8f) << row;     // the backdrop behind both
    EXPECT_EQ(g.tie_range.at(18, row, lo), g.tie_range.at(18, row, hi)) << row;
  }
}

// Every layer of a longer chain: three half-masked cards, the third white (its own texture, the
// same alpha), the backdrop (0.8) behind. On the centre column all three may flip; the reference
// keeps the first card, the surface behind it (the second card) and the chain's end (the backdrop)
// were the range's only other outcomes, so the white third card, which a correct GL shows when it
// cuts the first two and keeps the third, lay outside (hi 0.8). Two columns over every card passes
// for certain: one outcome, the first card, so a GL showing the third there still fails.
TEST(RasterTies, EveryFlipOfAChainOfThreeIsAdmitted) {
  Scene s = test::half_masked_card(true);
  test::add_card_quad(s, -0.1f, 1.0f, 0);
  s.textures.push_back(test::two_texel_texture("white_left_transparent", {255, 255, 255, 0, 255, 255, 255, 255}));
  Material white = s.materials[0];
  white.base_color_texture.texture = int(s.textures.size() - 1);
  s.materials.push_back(white);
  test::add_card_quad(s, -0.2f, 1.0f, uint32_t(s.materials.size() - 1));
  const GBuffer g = render_cards(s);
  const int lo = channel(g.tie_range, "albedo.0.lo"), hi = channel(g.tie_range, "albedo.0.hi");
  const float card = g.albedo.at(24, 16, 0);
  ASSERT_LT(card, 0.5f);
  for (int row = 10; row <= 22; ++row) {
    ASSERT_FLOAT_EQ(g.albedo.at(16, row, 0), card) << row;   // the reference keeps the first card
    EXPECT_GE(g.tie_range.at(16, row, hi), 0.99f) << row;    // the white third card
    EXPECT_FLOAT_EQ(g.tie_range.at(18, row, hi), card) << row;  // no flip: the first card alone
    EXPECT_FLOAT_EQ(g.tie_range.at(18, row, lo), card) << row;
  }
}

}  // namespace
}  // namespace vct

namespace vct {
namespace {

// A depth tie and an alpha flip at one centre (medium hunt seed 571, scenes/regressions/
// seed-571-medium): an opaque card (albedo 0.8) and the half-masked card coplanar with it, drawn
// after it, the cutoff just above the centre column's alpha (0.5). There the reference cuts the
// masked card and shows the opaque one, but a correct GL may keep the masked card (its test may
// flip) and, tied in depth, draw it in front: its grey texel joins the range. Two columns to the
// left the masked card is cut for certain: the opaque card alone.
TEST(RasterTies, AMaskedSurfaceTiedInDepthIsAdmittedWhereItsTestMayFlip) {
  Scene s = test::half_masked_card(false, AlphaMode::Mask, 0.502f);
  Material opaque = s.materials[0];
  opaque.alpha_mode = AlphaMode::Opaque;
  opaque.base_color_texture.texture = -1;
  opaque.base_color_factor = vec4(0.8f, 0.8f, 0.8f, 1.0f);
  s.materials.push_back(opaque);
  test::add_card_quad(s, 0.0f, 1.0f, uint32_t(s.materials.size() - 1));
  // The opaque card first in drawing order: at equal depths GL_LESS keeps it.
  std::rotate(s.triangles.begin(), s.triangles.begin() + 2, s.triangles.end());
  std::rotate(s.triangle_material.begin(), s.triangle_material.begin() + 2, s.triangle_material.end());
  const GBuffer g = render_cards(s);
  const int lo = channel(g.tie_range, "albedo.0.lo"), hi = channel(g.tie_range, "albedo.0.hi");
  const float card = g.albedo.at(24, 16, 0);  // right half: the masked card passes, tied, drawn second
  ASSERT_NEAR(card, 0.8f, 1e-6f);             // the reference shows the opaque card there too
  const float grey = 0.21586050f;             // the masked card's texel, 128 decoded from sRGB
  for (int row = 10; row <= 22; ++row) {
    ASSERT_FLOAT_EQ(g.albedo.at(16, row, 0), 0.8f) << row;
    EXPECT_LE(g.tie_range.at(16, row, lo), grey + 1e-3f) << row;  // the flip drawn in front
    EXPECT_FLOAT_EQ(g.tie_range.at(14, row, lo), 0.8f) << row;    // cut for certain
    EXPECT_FLOAT_EQ(g.tie_range.at(14, row, hi), 0.8f) << row;
  }
}

}  // namespace
}  // namespace vct
