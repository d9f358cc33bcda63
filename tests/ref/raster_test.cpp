// The software rasterizer against hand-checked coverage, the fill rule and exact interpolation.
#include <gtest/gtest.h>

#include <set>

#include "stages/raster.h"

namespace vct {
namespace {

// Clip-space vertex (w = 1) for a window position in a w x h viewport.
vec4 at_window(float x, float y, int w, int h, float z = 0.0f) {
  return vec4(x / float(w) * 2.0f - 1.0f, y / float(h) * 2.0f - 1.0f, z, 1.0f);
}

std::set<std::pair<int, int>> covered(const vec4 clip[3], int w, int h, int samples = 1) {
  std::vector<RasterTriangle> tris;
  setup_triangle(clip, w, h, 0, tris);
  std::set<std::pair<int, int>> out;
  for (const RasterTriangle& t : tris)
    rasterize(t, standard_sample_positions(samples), 0, w - 1, 0, h - 1,
              [&](const RasterFragment& f) { EXPECT_TRUE(out.insert({f.x, f.y}).second); });
  return out;
}

TEST(Raster, SingleTriangleCoversExactlyTheHandCountedPixels) {
  // Window (1,1), (6,1), (1,6): centres (x+.5, y+.5) strictly inside x+y+1 < 7, and on the
  // hypotenuse (x + y = 6) excluded: that edge is neither left nor top (it is a right edge).
  const vec4 c[3] = {at_window(1, 1, 8, 8), at_window(6, 1, 8, 8), at_window(1, 6, 8, 8)};
  std::set<std::pair<int, int>> expected;
  for (int y = 1; y < 8; ++y)
    for (int x = 1; x < 8; ++x)
      if (x + y <= 5) expected.insert({x, y});
  EXPECT_EQ(covered(c, 8, 8), expected);
  EXPECT_EQ(expected.size(), 10u);
  // Same triangle with the other winding: same pixels.
  const vec4 r[3] = {c[0], c[2], c[1]};
  EXPECT_EQ(covered(r, 8, 8), expected);
}

TEST(Raster, TopLeftRuleInYUpWindowCoordinates) {
  // Horizontal edge through the centres of row 4 (y = 4.5).
  // Interior below the edge -> it is a top edge -> row 4 covered.
  const vec4 top_edge[3] = {at_window(0.2f, 4.5f, 8, 8), at_window(7.8f, 4.5f, 8, 8), at_window(4, 0.2f, 8, 8)};
  const vec4 bottom_edge[3] = {at_window(0.2f, 4.5f, 8, 8), at_window(7.8f, 4.5f, 8, 8), at_window(4, 7.8f, 8, 8)};
  bool row4_top = false, row4_bottom = false;
  for (auto& p : covered(top_edge, 8, 8)) row4_top = row4_top || p.second == 4;
  for (auto& p : covered(bottom_edge, 8, 8)) row4_bottom = row4_bottom || p.second == 4;
  EXPECT_TRUE(row4_top);
  EXPECT_FALSE(row4_bottom);
  // Vertical edge through the centres of column 3 (x = 3.5): interior to the right = left edge.
  const vec4 left_edge[3] = {at_window(3.5f, 0.2f, 8, 8), at_window(7.8f, 4, 8, 8), at_window(3.5f, 7.8f, 8, 8)};
  const vec4 right_edge[3] = {at_window(3.5f, 0.2f, 8, 8), at_window(0.2f, 4, 8, 8), at_window(3.5f, 7.8f, 8, 8)};
  bool col3_left = false, col3_right = false;
  for (auto& p : covered(left_edge, 8, 8)) col3_left = col3_left || p.first == 3;
  for (auto& p : covered(right_edge, 8, 8)) col3_right = col3_right || p.first == 3;
  EXPECT_TRUE(col3_left);
  EXPECT_FALSE(col3_right);
}

TEST(Raster, SharedEdgesCoverEveryPixelExactlyOnce) {
  // A 16x16 viewport tiled by a mesh whose interior vertices sit on half-pixel positions, so many
  // pixel centres lie exactly on shared edges and vertices. Every pixel must be covered once.
  const int w = 16, h = 16, g = 4;
  std::vector<vec2> v;
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      float x = float(i) * 4.0f, y = float(j) * 4.0f;
      if (i > 0 && i < g) x += float((i * 7 + j * 3) % 5) * 0.5f - 1.0f;
      if (j > 0 && j < g) y += float((i * 5 + j * 11) % 5) * 0.5f - 1.0f;
      v.push_back({x + (i > 0 && i < g ? 0.5f : 0.0f), y + (j > 0 && j < g ? 0.5f : 0.0f)});
    }
  std::vector<int> count(size_t(w * h), 0);
  const std::vector<vec2>& centre = standard_sample_positions(1);
  auto tri = [&](int a, int b, int c) {
    const vec4 clip[3] = {at_window(v[size_t(a)].x, v[size_t(a)].y, w, h), at_window(v[size_t(b)].x, v[size_t(b)].y, w, h),
                          at_window(v[size_t(c)].x, v[size_t(c)].y, w, h)};
    std::vector<RasterTriangle> t;
    setup_triangle(clip, w, h, 0, t);
    for (auto& r : t) rasterize(r, centre, 0, w - 1, 0, h - 1, [&](const RasterFragment& f) { ++count[size_t(f.y * w + f.x)]; });
  };
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const int a = j * (g + 1) + i, b = a + 1, c = a + g + 2, d = a + g + 1;
      if ((i + j) % 2) {
        tri(a, b, c);
        tri(a, c, d);
      } else {  // other diagonal and clockwise winding: both orientations must obey the rule
        tri(a, d, b);
        tri(b, d, c);
      }
    }
  for (int i = 0; i < w * h; ++i) EXPECT_EQ(count[size_t(i)], 1) << "pixel " << i % w << "," << i / w;
}

TEST(Raster, PerspectiveCorrectBarycentricsReprojectToThePixelCentre) {
  const mat4 proj = glm::perspective(1.0f, 1.0f, 0.1f, 10.0f);
  const vec3 world[3] = {{-1.0f, -0.8f, -1.5f}, {1.2f, -0.5f, -6.0f}, {-0.2f, 1.0f, -3.0f}};
  vec4 clip[3];
  for (int i = 0; i < 3; ++i) clip[i] = proj * vec4(world[i], 1.0f);
  std::vector<RasterTriangle> t;
  setup_triangle(clip, 32, 32, 7, t);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].source, 7u);
  int n = 0;
  rasterize(t[0], standard_sample_positions(1), 0, 31, 0, 31, [&](const RasterFragment& f) {
    const vec3 p = f.bary.x * world[0] + f.bary.y * world[1] + f.bary.z * world[2];
    const vec4 c = proj * vec4(p, 1.0f);
    EXPECT_NEAR((c.x / c.w * 0.5f + 0.5f) * 32.0f, float(f.x) + 0.5f, 2e-3f);
    EXPECT_NEAR((c.y / c.w * 0.5f + 0.5f) * 32.0f, float(f.y) + 0.5f, 2e-3f);
    EXPECT_NEAR(c.z / c.w * 0.5f + 0.5f, f.depth, 1e-5f);  // depth is the window depth of that point
    EXPECT_NEAR(f.bary.x + f.bary.y + f.bary.z, 1.0f, 1e-6f);
    ++n;
  });
  EXPECT_GT(n, 50);
}

TEST(Raster, NearPlaneClippingKeepsTheVisiblePart) {
  const mat4 proj = glm::perspective(1.2f, 1.0f, 0.5f, 10.0f);
  // One vertex behind the camera: only the part beyond z = -0.5 may produce fragments.
  const vec3 world[3] = {{-1.0f, -1.0f, -3.0f}, {1.0f, -1.0f, -3.0f}, {0.0f, -1.0f, 2.0f}};
  vec4 clip[3];
  for (int i = 0; i < 3; ++i) clip[i] = proj * vec4(world[i], 1.0f);
  std::vector<RasterTriangle> t;
  setup_triangle(clip, 32, 32, 0, t);
  ASSERT_GE(t.size(), 1u);
  int n = 0;
  for (auto& r : t)
    rasterize(r, standard_sample_positions(1), 0, 31, 0, 31, [&](const RasterFragment& f) {
      const vec3 p = f.bary.x * world[0] + f.bary.y * world[1] + f.bary.z * world[2];
      EXPECT_LT(p.z, -0.5f + 1e-4f);
      EXPECT_NEAR(p.y, -1.0f, 1e-5f);
      const vec4 c = proj * vec4(p, 1.0f);
      EXPECT_NEAR((c.x / c.w * 0.5f + 0.5f) * 32.0f, float(f.x) + 0.5f, 2e-3f);
      ++n;
    });
  EXPECT_GT(n, 20);
}

TEST(Raster, MsaaCoverageMasks) {
  // A pixel cut by the vertical line x = 0.5 of the pixel (interior to the right): of the 4x
  // standard samples (x = .375, .875, .125, .625) samples 1 and 3 are covered.
  const vec4 c[3] = {at_window(2.5f, -0.5f, 4, 4), at_window(3.9f, 1.5f, 4, 4), at_window(2.5f, 3.5f, 4, 4)};
  std::vector<RasterTriangle> t;
  setup_triangle(c, 4, 4, 0, t);
  ASSERT_EQ(t.size(), 1u);
  uint32_t mask = 0;
  rasterize(t[0], standard_sample_positions(4), 2, 2, 1, 1, [&](const RasterFragment& f) { mask = f.coverage; });
  EXPECT_EQ(mask, 0b1010u);
  EXPECT_EQ(standard_sample_positions(8).size(), 8u);
  EXPECT_THROW(standard_sample_positions(2), std::invalid_argument);
}

TEST(Raster, VisibilityBufferDepthTestAndRowOrder) {
  // Two overlapping quads in an orthographic view: the nearer wins; row 0 is the top.
  std::vector<vec3> pos = {{-1, 0, -0.5f}, {1, 0, -0.5f}, {1, 1, -0.5f}, {-1, 1, -0.5f},
                           {-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}};
  std::vector<uvec3> tris = {{4, 5, 6}, {4, 6, 7}, {0, 1, 2}, {0, 2, 3}};
  const VisibilityBuffer vb = render_visibility(pos, tris, mat4(1.0f), 4, 4);
  // Upper half (rows 0,1 = window y 2,3): quad at z=-0.5 (depth 0.25) drawn later but nearer.
  EXPECT_EQ(vb.triangle[vb.index(1, 0)] / 2, 1);
  EXPECT_FLOAT_EQ(vb.depth[vb.index(1, 0)], 0.25f);
  EXPECT_EQ(vb.triangle[vb.index(1, 3)] / 2, 0);
  EXPECT_FLOAT_EQ(vb.depth[vb.index(1, 3)], 0.75f);
}

}  // namespace
}  // namespace vct
