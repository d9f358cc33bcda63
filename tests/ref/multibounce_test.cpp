// Temporal multibounce in a closed emissive box: energy rises monotonically (restitution < 1)
// and converges, and stays below the furnace bound Le / (1 - restitution * albedo).
#include <gtest/gtest.h>

#include "stages/multibounce.h"
#include "test_box_scene.h"

namespace vct {
namespace {

TEST(Multibounce, ClosedBoxConvergesWithMonotoneEnergy) {
  const vec3 albedo(0.8f), le(1.0f);
  const Scene scene = test::closed_box(albedo, le);
  VctSettings s;
  s.grid = 16;
  s.bounces = 12;
  s.restitution = 0.5f;
  s.particles = false;
  const Voxelization vox = voxelize_conservative(scene, s.grid);
  const MultibounceResult r = inject_with_multibounce(scene, vox, {}, s);
  ASSERT_EQ(r.frames, 12);
  ASSERT_EQ(r.energy.size(), 12u);
  const double covered = double(vox.covered);
  // Frame 1: emission only, Le in each of three channels of every occupied voxel.
  EXPECT_NEAR(r.energy[0], 3.0 * covered, 1e-3 * covered);
  for (size_t k = 1; k < r.energy.size(); ++k) {
    EXPECT_GE(r.energy[k], r.energy[k - 1]) << "frame " << k;
  }
  // Contraction: each change smaller than the previous one, the last one tiny.
  const double first_gain = r.energy[1] - r.energy[0];
  EXPECT_GT(first_gain, 0.05 * r.energy[0]);  // the bounce really adds light
  for (size_t k = 2; k < r.energy.size(); ++k) {
    EXPECT_LE(r.energy[k] - r.energy[k - 1], r.energy[k - 1] - r.energy[k - 2] + 1e-6);
  }
  EXPECT_LT((r.energy.back() - r.energy[r.energy.size() - 2]) / r.energy.back(), 1e-3);
  // Furnace bound: cones see at most the wall radiance, so L <= Le / (1 - r * albedo).
  EXPECT_LE(r.energy.back(), 3.0 * covered / (1.0 - 0.5 * 0.8) * (1.0 + 1e-4));
}

TEST(Multibounce, ToleranceStopsEarly) {
  const Scene scene = test::closed_box(vec3(0.8f), vec3(1.0f));
  VctSettings s;
  s.grid = 16;
  s.bounces = 40;
  s.convergence_tolerance = 1e-2f;
  s.particles = false;
  const MultibounceResult r = inject_with_multibounce(scene, voxelize_conservative(scene, s.grid), {}, s);
  EXPECT_LT(r.frames, 40);
  const double last = r.energy.back(), before = r.energy[r.energy.size() - 2];
  EXPECT_LE((last - before) / before, 1e-2);
}

TEST(Multibounce, OneBounceIsDirectOnly) {
  const Scene scene = test::closed_box(vec3(0.8f), vec3(0.5f));
  VctSettings s;
  s.grid = 16;
  s.bounces = 1;
  s.particles = false;
  const Voxelization vox = voxelize_conservative(scene, s.grid);
  const MultibounceResult r = inject_with_multibounce(scene, vox, {}, s);
  EXPECT_EQ(r.frames, 1);
  EXPECT_NEAR(r.energy[0], 1.5 * double(vox.covered), 1e-3 * double(vox.covered));
}

}  // namespace
// The stop rule is relative to the frame before (both backends call this function): near the
// threshold a rule relative to the newer frame would stop one frame earlier on one side.
TEST(Multibounce, StopRuleIsRelativeToTheFrameBefore) {
  EXPECT_FALSE(multibounce_converged({1.0}, 0.1f));         // one frame: nothing to compare
  EXPECT_FALSE(multibounce_converged({1.0, 1.05}, 0.0f));   // tolerance 0: run every frame
  EXPECT_TRUE(multibounce_converged({1.0, 1.0999}, 0.1f));
  EXPECT_FALSE(multibounce_converged({1.0, 1.105}, 0.1f));  // 0.105 > 0.1 * 1.0 (but <= 0.1 * 1.105)
  EXPECT_TRUE(multibounce_converged({0.0, 0.0}, 0.1f));     // a dark scene has converged
  EXPECT_FALSE(multibounce_converged({0.0, 1e-9}, 0.1f));
}

}  // namespace vct
