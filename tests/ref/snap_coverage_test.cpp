// The voxel raster's coverage under a per-vertex snap (stages/raster.h SnapWorld,
// stages/raster.h edge_snap_reach): every one of the 3^6 snaps of a triangle's vertices by -1, 0 or
// +1 subpixel step per axis covers a sample the Certain world covers, and covers only samples the
// Possible world covers; a sample on an edge (the top-left rule covers it) is not certain.
#include <gtest/gtest.h>
#include <random>

#include "stages/raster.h"

namespace vct {
namespace {

RasterTriangle triangle(const int64_t x[3], const int64_t y[3]) {
  RasterTriangle t{};
  for (int i = 0; i < 3; ++i) t.x[i] = x[i], t.y[i] = y[i];
  return t;
}

int64_t area2(const RasterTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
}

bool covers(const RasterTriangle& t, int64_t px, int64_t py, SnapWorld world) {
  return covered_in_world(t, edge_setup(t), world, px, py);
}

TEST(SnapCoverage, EveryPerVertexSnapLiesBetweenTheCertainAndPossibleWorlds) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int64_t> coord(0, 40), near(-6, 46);
  int certain_checked = 0, possible_checked = 0;
  for (int trial = 0; trial < 800; ++trial) {
    int64_t x[3], y[3];
    for (int i = 0; i < 3; ++i) x[i] = coord(rng), y[i] = coord(rng);
    RasterTriangle t = triangle(x, y);
    if (area2(t) <= 0) continue;  // counter-clockwise, as setup_triangle leaves every triangle
    for (int s = 0; s < 30; ++s) {
      const int64_t px = near(rng), py = near(rng);
      const bool certain = covers(t, px, py, SnapWorld::Certain), possible = covers(t, px, py, SnapWorld::Possible);
      bool all = true, some = false;
      for (int combo = 0; combo < 729; ++combo) {
        int64_t sx[3], sy[3];
        for (int i = 0, c = combo; i < 3; ++i, c /= 9) sx[i] = x[i] + c % 3 - 1, sy[i] = y[i] + (c / 3) % 3 - 1;
        const RasterTriangle u = triangle(sx, sy);
        const bool in = area2(u) > 0 && covers(u, px, py, SnapWorld::Reference);
        all = all && in;
        some = some || in;
      }
      if (certain) EXPECT_TRUE(all) << "trial " << trial << " sample " << px << "," << py;
      if (some) EXPECT_TRUE(possible) << "trial " << trial << " sample " << px << "," << py;
      certain_checked += certain, possible_checked += some;
    }
  }
  EXPECT_GT(certain_checked, 200);
  EXPECT_GT(possible_checked, 600);
}

// Seed 2429's fragment: its only covered sample lies on a horizontal top edge (e = 0, covered by
// the top-left rule); a snap of that edge's vertices one step down uncovers it, and llvmpipe did
// not write it. The Certain world does not count it; the Possible world does.
TEST(SnapCoverage, ASampleOnATopEdgeIsNotCertain) {
  const int64_t x[3] = {0, 400, 800}, y[3] = {96, -300, 96};  // counter-clockwise, y up: top edge y = 96
  const RasterTriangle t = triangle(x, y);
  ASSERT_GT(area2(t), 0);
  EXPECT_TRUE(covers(t, 400, 96, SnapWorld::Reference));
  EXPECT_FALSE(covers(t, 400, 96, SnapWorld::Certain));
  EXPECT_TRUE(covers(t, 400, 96, SnapWorld::Possible));
  EXPECT_TRUE(covers(t, 400, 0, SnapWorld::Certain));  // well inside: certain
}

// Every snapped triangle lies in its vertices' box grown by one step, so the Possible world covers
// nothing beyond it, however far an edge's reach alone would let it (medium hunt seed 145: a
// heightfield of triangles a few steps wide "possibly" covered most pixels around each). A triangle
// 3 steps wide and 1 high: a sample 200 steps along its bottom edge's line is within every edge's
// reach (the slanted edge's function is -197 there, its reach 402), but no snap covers it; one step
// outside the box is the limit.
TEST(SnapCoverage, PossibleCoversNothingBeyondTheVerticesBoxGrownByOneStep) {
  const int64_t x[3] = {0, 3, 0}, y[3] = {0, 0, 1};
  const RasterTriangle t = triangle(x, y);
  ASSERT_GT(area2(t), 0);
  const EdgeSetup e = edge_setup(t);
  for (int i = 0; i < 3; ++i)  // the reach alone would cover it
    EXPECT_GE(e.a[i] * 200 + e.b[i] * 0 + e.c[i] + edge_snap_reach(t, i, 200, 0), 0) << i;
  EXPECT_FALSE(covers(t, 200, 0, SnapWorld::Possible));
  EXPECT_TRUE(covers(t, 4, 0, SnapWorld::Possible));   // vertex (3, 0) snapped to (4, 0) covers it
  EXPECT_FALSE(covers(t, 5, 0, SnapWorld::Possible));  // two steps out: no snap reaches
  EXPECT_TRUE(covers(t, -1, -1, SnapWorld::Possible));
  EXPECT_FALSE(covers(t, -2, 0, SnapWorld::Possible));
}

}  // namespace
}  // namespace vct
