// vct validate builds the reference's stage set by moving the stages out of its frame
// (stage_set_from_frame(FrameResult&&), docs/performance.md "Validate at grid 256"): the set must
// be the copied set stage for stage, bit for bit, in every mode that adds stages (anisotropic
// mips, multibounce frames, CAS bounds); and a set without its stages keeps every other field.
#include <gtest/gtest.h>

#include <utility>

#include "compare/stage_set.h"
#include "freedoms/reference_frame.h"
#include "scene/gltf_loader.h"

namespace vct::cmp {
namespace {

Settings small() {
  Settings s;
  s.vct.width = s.vct.height = 24;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 64;
  return s;
}

void expect_moved_equals_copied(const Settings& s) {
  const Scene scene = load_scene("");
  FrameResult frame = render_ref_frame(scene, s);
  const StageSet copied = stage_set_from_frame(frame, s.vct);
  const StageSet moved = stage_set_from_frame(std::move(frame), s.vct);
  ASSERT_EQ(moved.images.size(), copied.images.size());
  ASSERT_EQ(moved.volumes.size(), copied.volumes.size());
  EXPECT_GT(copied.volumes.size(), 5u);
  for (const auto& [name, img] : copied.images) {
    ASSERT_TRUE(moved.images.count(name)) << name;
    EXPECT_EQ(moved.images.at(name).data, img.data) << name;
    EXPECT_EQ(moved.images.at(name).channels, img.channels) << name;
  }
  for (const auto& [name, vol] : copied.volumes) {
    ASSERT_TRUE(moved.volumes.count(name)) << name;
    EXPECT_EQ(moved.volumes.at(name).data, vol.data) << name;
    EXPECT_EQ(moved.volumes.at(name).nx, vol.nx) << name;
  }
  EXPECT_EQ(moved.backend, copied.backend);
  EXPECT_EQ(moved.reduction, copied.reduction);
  EXPECT_EQ(moved.settings, copied.settings);
  // What the set took is gone from the frame; the mips' base level (no stage) stays.
  EXPECT_TRUE(frame.voxels.radiance.data.empty());
  EXPECT_TRUE(frame.images.final_image.data.empty());
  EXPECT_FALSE(frame.mips.iso.empty() || frame.mips.iso[0].data.empty());
}

TEST(StageSetMove, MovedSetEqualsTheCopiedOne) { expect_moved_equals_copied(small()); }

// The variant with the most volumes: anisotropic mips, bounce frames, CAS bounds.
Settings anisotropic_multibounce_cas() {
  Settings s = small();
  s.vct.anisotropic = true;
  s.vct.bounces = 2;
  s.vct.reduction = Reduction::CasRgba8;
  return s;
}

TEST(StageSetMove, MovedSetEqualsTheCopiedOneAnisotropicMultibounceCas) {
  expect_moved_equals_copied(anisotropic_multibounce_cas());
}

// vct validate's GL frame gives only its voxel grid to its set (stage_set_taking_voxels): the set
// is the copied one bit for bit, the frame keeps everything the passes on its own inputs read
// (mips, shadow maps, G-buffer, images, bounce volumes) and has no grid left.
void expect_taking_voxels_equals_copied(const Settings& s) {
  const Scene scene = load_scene("");
  FrameResult frame = render_ref_frame(scene, s);
  const StageSet copied = stage_set_from_frame(frame, s.vct);
  const StageSet taken = stage_set_taking_voxels(frame, s.vct);
  ASSERT_EQ(taken.images.size(), copied.images.size());
  ASSERT_EQ(taken.volumes.size(), copied.volumes.size());
  for (const auto& [name, img] : copied.images) EXPECT_EQ(taken.images.at(name).data, img.data) << name;
  for (const auto& [name, vol] : copied.volumes) {
    EXPECT_EQ(taken.volumes.at(name).data, vol.data) << name;
    EXPECT_EQ(taken.volumes.at(name).nx, vol.nx) << name;
  }
  EXPECT_EQ(frame.voxels.radiance.voxel_count(), 0u);  // emptied, sizes too: nothing reads a stale grid
  EXPECT_EQ(frame.voxels.fragments.voxel_count(), 0u);
  EXPECT_TRUE(frame.voxels.shading_slack.data.empty());
  EXPECT_EQ(copied.volumes.at("voxel.radiance").voxel_count(), size_t(s.vct.grid) * s.vct.grid * s.vct.grid);
  EXPECT_FALSE(frame.mips.iso.empty() || frame.mips.iso[0].data.empty());
  EXPECT_FALSE(frame.mips.iso.size() < 2 || frame.mips.iso[1].data.empty());
  EXPECT_FALSE(frame.images.final_image.data.empty());
  EXPECT_FALSE(frame.gbuffer.position.data.empty());
  EXPECT_FALSE(frame.shadow_maps.empty() || frame.shadow_maps[0].depth.data.empty());
  if (s.vct.bounces > 1) EXPECT_FALSE(frame.bounce_input.data.empty());
}

TEST(StageSetMove, TakingVoxelsEqualsTheCopiedSetAndKeepsTheRest) { expect_taking_voxels_equals_copied(small()); }

TEST(StageSetMove, TakingVoxelsAnisotropicMultibounceCas) {
  expect_taking_voxels_equals_copied(anisotropic_multibounce_cas());
}

TEST(StageSetMove, WithoutStagesKeepsEveryOtherField) {
  StageSet set;
  set.backend = "gl";
  set.storage = "rgba8";
  set.reduction = "cas_rgba8";
  set.settings = {{"grid", 32}};
  set.info = {{"note", "x"}};
  set.facts.renderer = "llvmpipe";
  set.conventions.display = DisplayTransform();
  set.root = "/tmp/run/gl";
  set.files["image.final"] = "image_final.exr";
  set.images["image.final"] = Image(2, 2, 3, 1.0f);
  set.volumes["voxel.radiance"] = Volume(2, 2, 2, 4);
  const StageSet bare = stage_set_without_stages(set);
  EXPECT_TRUE(bare.images.empty());
  EXPECT_TRUE(bare.volumes.empty());
  EXPECT_EQ(bare.backend, "gl");
  EXPECT_EQ(bare.storage, "rgba8");
  EXPECT_EQ(bare.reduction, "cas_rgba8");
  EXPECT_EQ(bare.settings, set.settings);
  EXPECT_EQ(bare.info, set.info);
  EXPECT_EQ(bare.facts.renderer, "llvmpipe");
  EXPECT_EQ(bare.root, "/tmp/run/gl");
  EXPECT_EQ(bare.files, set.files);
}

}  // namespace
}  // namespace vct::cmp
