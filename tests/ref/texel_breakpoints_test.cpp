// Where a NEAREST lookup changes texel inside the snap square (freedoms/texel_breakpoints.h), and
// the light's extremes over the square that those points reach.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "freedoms/texel_breakpoints.h"

namespace vct {
namespace {

// A square of half-width 0.25 mapped at two texels per unit around (0.7, 0.3): texel coordinates
// [0.2, 1.2] x [-0.2, 0.8], cut by x = 1 and y = 0 into four rectangles, whose corners in window
// offsets are du in {-0.25, 0.15, 0.25} and dv in {-0.25, -0.15, 0.25}. Each piece gives its four
// corners, each pulled a sixty-fourth of the way to the piece's centre.
TEST(TexelBreakpoints, HandWorkedSquare) {
  const TexelMap m{{0.7, 0.3}, {2.0, 0.0}, {0.0, 2.0}};
  std::vector<glm::dvec2> out;
  ASSERT_TRUE(texel_breakpoints(m, 0.25, 100, out));
  ASSERT_EQ(out.size(), 16u);
  const double us[2][2] = {{-0.25, 0.15}, {0.15, 0.25}}, vs[2][2] = {{-0.25, -0.15}, {-0.15, 0.25}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const glm::dvec2 centre(0.5 * (us[i][0] + us[i][1]), 0.5 * (vs[j][0] + vs[j][1]));
      for (double u : us[i])
        for (double v : vs[j]) {
          const glm::dvec2 expected = glm::dvec2(u, v) + (centre - glm::dvec2(u, v)) / 64.0;
          const bool found = std::any_of(out.begin(), out.end(), [&](const glm::dvec2& p) {
            return glm::length(p - expected) < 1e-12;
          });
          EXPECT_TRUE(found) << "piece (" << i << ", " << j << ") corner (" << u << ", " << v << ")";
        }
    }
}

// A texel corner just inside the square's edge leaves a sliver of a third texel: it gets its own
// points (a fixed offset off the lines would land outside the square, or in the next texel).
TEST(TexelBreakpoints, ASliverAtTheEdgeGetsItsOwnPoints) {
  // Texel coordinates x = 10 du + 0.999, y = 10 dv + 0.999 over [-0.1, 0.1]^2: [-0.001, 1.999]^2,
  // the texels x = -1 and y = -1 only in slivers 0.001 wide.
  const TexelMap m{{0.999, 0.999}, {10.0, 0.0}, {0.0, 10.0}};
  std::vector<glm::dvec2> out;
  ASSERT_TRUE(texel_breakpoints(m, 0.1, 1000, out));
  int in_corner_sliver = 0;
  for (const glm::dvec2& p : out) {
    const glm::dvec2 t = m.at_centre + p.x * m.per_u + p.y * m.per_v;
    if (std::floor(t.x) == -1.0 && std::floor(t.y) == -1.0) ++in_corner_sliver;
    EXPECT_LE(std::abs(p.x), 0.1);
    EXPECT_LE(std::abs(p.y), 0.1);
  }
  EXPECT_EQ(in_corner_sliver, 4);  // the 0.001 x 0.001 corner piece: its four corners
}

TEST(TexelBreakpoints, RefusesMoreThanTheCap) {
  const TexelMap m{{0.5, 0.5}, {100.0, 0.0}, {0.0, 100.0}};  // 50 x 50 texels inside the square
  std::vector<glm::dvec2> out;
  EXPECT_FALSE(texel_breakpoints(m, 0.25, 4096, out));
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(texel_breakpoints(m, 0.25, 100000, out));
}

// A piecewise-constant texture under a slowly varying light: f = texel value + a small slope. Its
// largest and smallest values over the square, found on a dense grid, are reached (within the
// slope times a sixty-fourth of a piece, at most 1.5/64 texel along each axis) by the points; the
// square's corners alone miss them (a brighter texel inside, or a bright texel's nearest point on
// a line).
TEST(TexelBreakpoints, CornersAndBreakpointsReachTheExtremesOfAPiecewiseLight) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto texel_value = [](double x, double y) {
    const uint32_t h = uint32_t(int64_t(std::floor(x)) * 73856093) ^ uint32_t(int64_t(std::floor(y)) * 19349663);
    return double((h * 2654435761u) >> 8) / double(1 << 24);
  };
  int corners_missed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double r = 0.01;
    const TexelMap m{{10.0 * u(rng), 10.0 * u(rng)}, {150.0 * u(rng), 150.0 * u(rng)}, {150.0 * u(rng), 150.0 * u(rng)}};
    const glm::dvec2 slope(0.3 * u(rng), 0.3 * u(rng));  // light units per texel
    const auto f = [&](const glm::dvec2& d) {
      const glm::dvec2 t = m.at_centre + d.x * m.per_u + d.y * m.per_v;
      return texel_value(t.x, t.y) + glm::dot(slope, t - m.at_centre);
    };
    std::vector<glm::dvec2> points = {{-r, -r}, {r, -r}, {-r, r}, {r, r}};
    double corner_hi = -1e9;
    for (const glm::dvec2& c : points) corner_hi = std::max(corner_hi, f(c));
    ASSERT_TRUE(texel_breakpoints(m, r, 4096, points));
    double hi = -1e9, lo = 1e9, dense_hi = -1e9, dense_lo = 1e9;
    for (const glm::dvec2& p : points) hi = std::max(hi, f(p)), lo = std::min(lo, f(p));
    constexpr int kDense = 300;
    for (int i = 0; i <= kDense; ++i)
      for (int j = 0; j <= kDense; ++j) {
        const double v = f({r * (2.0 * i / kDense - 1.0), r * (2.0 * j / kDense - 1.0)});
        dense_hi = std::max(dense_hi, v), dense_lo = std::min(dense_lo, v);
      }
    const double side = 1.5 * (std::abs(slope.x) + std::abs(slope.y)) / 64.0;
    EXPECT_GE(hi, dense_hi - side - 1e-12) << "trial " << trial;
    EXPECT_LE(lo, dense_lo + side + 1e-12) << "trial " << trial;
    if (corner_hi < dense_hi - 0.01) ++corners_missed;
  }
  EXPECT_GT(corners_missed, 50);  // the corners alone would not do
}

}  // namespace
}  // namespace vct
