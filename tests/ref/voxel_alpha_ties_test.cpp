// Alpha-mask ties of the voxel raster (freedoms/voxel_alpha_ties.h), on the alpha card
// (alpha_card_scene.h) with its texture replaced by a constant alpha a against the cutoff 1/2: the
// freedom there is kAlphaWeightSlack = 3/512 alone (a constant alpha does not move with the
// sample), so every fragment ties when |a - 1/2| <= 3/512 and none does beyond it.
#include <gtest/gtest.h>

#include "alpha_card_scene.h"
#include "freedoms/alpha_ties.h"
#include "freedoms/coverage_ties.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

constexpr int kGrid = 16;

Scene card_of_constant_alpha(float alpha) {
  Scene s = test::half_masked_card(false);
  s.materials[0].base_color_texture.texture = -1;
  s.materials[0].base_color_factor.a = alpha;
  // The card's plane a third of a voxel inside its layer: no fragment within a depth tie's reach
  // of a voxel boundary (coverage_ties.h), so every tie below is an alpha tie.
  s.volume.origin.z -= s.volume.size / float(kGrid) / 3.0f;
  return s;
}

struct Ties {
  size_t kept = 0, may_drop = 0, may_add = 0;
  float occupancy_ties = 0.0f;
};

// The card unmasked: its fragments and occupied voxels (the same raster at alpha 1).
Voxelization unmasked_card() { return voxelize_gpu_rule(card_of_constant_alpha(1.0f), kGrid, 4); }

Ties ties_of(float alpha) {
  const Scene s = card_of_constant_alpha(alpha);
  Voxelization vox = voxelize_gpu_rule(s, kGrid, 4);
  add_coverage_ties(s, vox);
  Ties t;
  t.kept = vox.fragments.size();
  for (uint8_t d : vox.may_drop) t.may_drop += d;
  t.may_add = vox.may_add.size();
  for (float v : occupancy_ties(vox).data) t.occupancy_ties += v;
  return t;
}

TEST(VoxelAlphaTies, AtTheCutoffEveryKeptFragmentMayDrop) {
  // alpha == cutoff passes (glTF: cut only below the cutoff), and may flip: every voxel may empty.
  const Voxelization card = unmasked_card();
  const Ties t = ties_of(0.5f);
  ASSERT_EQ(t.kept, card.fragments.size());
  ASSERT_GT(card.covered, 100);
  EXPECT_EQ(t.may_drop, t.kept);
  EXPECT_EQ(t.may_add, 0u);
  EXPECT_EQ(t.occupancy_ties, float(card.covered));
}

TEST(VoxelAlphaTies, JustBelowTheCutoffEveryCutFragmentMayBeAdded) {
  const Voxelization card = unmasked_card();
  const Ties t = ties_of(0.5f - 5.0f / 1024.0f);  // 2.5/512 below: inside the 3/512
  EXPECT_EQ(t.kept, 0u);
  EXPECT_EQ(t.may_add, card.fragments.size());
  EXPECT_EQ(t.occupancy_ties, float(card.covered));
}

TEST(VoxelAlphaTies, BeyondTheWeightsFreedomNothingTies) {
  // 3.5/512 off the cutoff on either side: one outcome, the reference's (a GL that keeps or drops
  // these fragments is wrong, and the occupancy judge fails it: no coverage-tie flags them).
  const Ties below = ties_of(0.5f - 7.0f / 1024.0f);
  EXPECT_EQ(below.kept, 0u);
  EXPECT_EQ(below.may_add, 0u);
  EXPECT_EQ(below.occupancy_ties, 0.0f);
  const Ties above = ties_of(0.5f + 7.0f / 1024.0f);
  EXPECT_EQ(above.kept, unmasked_card().fragments.size());
  EXPECT_EQ(above.may_drop, 0u);
}

}  // namespace
}  // namespace vct
