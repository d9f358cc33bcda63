// The up-front memory check: hand-computed estimates and the refusal message.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"

namespace vct {
namespace {

// One bounce, isotropic, conservative voxelizer, exact mean: every term by hand.
TEST(MemoryBudget, EstimateMatchesHandCount) {
  Settings s;
  s.vct.grid = 64;
  s.vct.anisotropic = false;
  s.vct.bounces = 1;
  s.vct.voxelizer = Voxelizer::Conservative;
  s.vct.reduction = Reduction::ExactMean;
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 50;
  s.pt.width = s.pt.height = 10;
  const MemoryEstimate e = estimate_memory(s);
  const uint64_t n3 = 64ull * 64 * 64;
  const uint64_t occupancy = 8 * n3;  // Voxelization::occupancy + FrameResult's copy (float)
  const uint64_t grid = 20 * n3;      // RGBA float radiance + float fragment count
  // iso[0] copies the base; levels 1..6 hold 32^3 + 16^3 + ... + 1 = 37449 voxels.
  const uint64_t mips = 16 * n3 + 16 * 37449;
  const uint64_t fragments = 8 * 64 * 64 * 157;  // 8 N^2 fragments, 157 B each (12 of them the kept light)
  EXPECT_EQ(e.voxels, occupancy + grid + mips + fragments);
  EXPECT_EQ(e.voxels, 17278096u);
  // Shadow map 50^2 floats and its range (two floats per texel); per pixel: G-buffer 84 + its
  // visibility buffer kept for the freedoms 22 + texture slack 24 + raster alternatives 168 + frame
  // images 96 + cone images 2 x 80.
  EXPECT_EQ(e.images, 50ull * 50 * 12 + 100ull * 100 * 554);
  // The camera's two more visibility buffers and the depth ties' doubles (2 x 22 + 16) are larger.
  EXPECT_EQ(e.raster_scratch, 100ull * 100 * 60);
  EXPECT_EQ(e.path_tracer, 100ull * (16 * 8 + 256));  // accumulators + the kept first vertices
  EXPECT_EQ(e.baseline, 136ull << 20);
  EXPECT_EQ(e.total(), e.baseline + e.voxels + e.images + e.path_tracer);
  // Shadow maps are rasterized depth-only, but their range of alternatives needs up to 82 B per
  // texel while it is found (with alpha masks: three visibility buffers, the doubles of the
  // surfaces behind), one map at a time: a large map's scratch outweighs a small image's.
  s.vct.shadow_map_size = 2048;
  const MemoryEstimate big_map = estimate_memory(s);
  EXPECT_EQ(big_map.raster_scratch, 2048ull * 2048 * 82);
  EXPECT_EQ(big_map.images, 2048ull * 2048 * 12 + 100ull * 100 * 554);
  // A large image's visibility buffer outweighs a small grid; only the larger counts.
  s.vct.grid = 16;
  s.vct.shadow_map_size = 50;
  s.vct.width = s.vct.height = 2048;
  const MemoryEstimate big_image = estimate_memory(s);
  EXPECT_EQ(big_image.raster_scratch, 2048ull * 2048 * 60);
  EXPECT_GT(big_image.raster_scratch, big_image.voxels);
  EXPECT_EQ(big_image.total(), big_image.baseline + big_image.raster_scratch + big_image.images + big_image.path_tracer);
}

// Every diffuse cone keeps an RGBA float image, twice while it is copied into the frame.
TEST(MemoryBudget, ConeImagesFollowTheConeCount) {
  Settings s;
  s.vct.width = s.vct.height = 10;
  s.vct.diffuse_cone_count = 16;
  const uint64_t sixteen = estimate_memory(s).images;
  s.vct.diffuse_cone_count = 5;
  EXPECT_EQ(sixteen - estimate_memory(s).images, 100ull * 11 * 2 * 16);
  s.vct.diffuse_cones = false;
  EXPECT_EQ(estimate_memory(s).images, uint64_t(s.vct.shadow_map_size) * s.vct.shadow_map_size * 12 + 100ull * 394);  // 84 + 22 + 24 + 168 + 96
}

// Each light's shadow maps count: one square float map per spot or directional light, six per
// point light (shadow_map_layers), each with its two-float range; without a scene, one.
TEST(MemoryBudget, ShadowMapsFollowTheLights) {
  Settings s;
  s.vct.shadow_map_size = 512;
  const uint64_t one = estimate_memory(s).images;
  EXPECT_EQ(estimate_memory(s, 1).images, one);
  // A sun and two point lamps (sun_room): 1 + 6 + 6 maps.
  EXPECT_EQ(estimate_memory(s, 13).images - one, 12ull * 512 * 512 * 12);  // map + range
  EXPECT_EQ(estimate_memory(s, 0).images, one - 512ull * 512 * 12);
}

// A loaded scene adds kBytesPerTriangle (600 B, measured: bench/memory_bench.py) per triangle and
// its decoded texels; without alpha masks a shadow map's ties need no full-map scratch.
TEST(MemoryBudget, SceneTermsFollowTrianglesTexturesAndMasks) {
  Settings s;
  s.vct.grid = 16;  // voxels below either scratch: the larger scratch is what the total counts
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 2048;
  SceneFootprint scene;
  scene.triangles = 1000000;
  scene.texture_bytes = 4ull * 1024 * 1024;
  const MemoryEstimate masked = estimate_memory(s, scene);
  EXPECT_EQ(masked.scene, 600000000ull + 4194304ull);
  EXPECT_EQ(masked.raster_scratch, 2048ull * 2048 * 82);
  scene.alpha_tested = false;
  const MemoryEstimate opaque = estimate_memory(s, scene);
  EXPECT_EQ(opaque.raster_scratch, 100ull * 100 * 60);  // the camera's scratch only
  ASSERT_LT(opaque.voxels, opaque.raster_scratch);
  EXPECT_EQ(masked.total() - opaque.total(), 2048ull * 2048 * 82 - 100ull * 100 * 60);
  // Without a scene: no scene term, masks assumed (the estimate validate_settings checks).
  EXPECT_EQ(estimate_memory(s).scene, 0u);
  EXPECT_EQ(estimate_memory(s).raster_scratch, 2048ull * 2048 * 82);
}

// The warning before a run that may not fit: said when the estimate exceeds the machine, not otherwise.
TEST(MemoryBudget, WarnsWhenTheEstimateExceedsTheMachine) {
  Settings s;
  const MemoryEstimate e = estimate_memory(s);
  EXPECT_FALSE(warn_if_memory_short(e, "test", e.total()));
  EXPECT_TRUE(warn_if_memory_short(e, "test", e.total() - 1));
  EXPECT_FALSE(warn_if_memory_short(e, "test", 0));  // unknown machine size
}

// Multibounce keeps two mip pyramids (or two grids) and, while small, every earlier frame.
TEST(MemoryBudget, MultibounceAnisotropicHandCount) {
  Settings s;
  s.vct.grid = 16;
  s.vct.anisotropic = true;
  s.vct.bounces = 3;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::ExactMean;
  const uint64_t n3 = 16ull * 16 * 16;
  const uint64_t occupancy = 12 * n3;  // occupancy, conservative copy, hole map (float each)
  const uint64_t grid = 20 * n3;       // RGBA float + fragment count
  // iso[0] copy; the iso pyramid and six directional ones, levels 1..4: 512 + 64 + 8 + 1 = 585.
  const uint64_t mips = 16 * n3 + 7 * 16 * 585;
  const uint64_t fragments = 8 * 16 * 16 * 157;
  const uint64_t kept = 2 * 16 * n3;  // base levels of frames 1 and 2 (RGBA float)
  EXPECT_EQ(estimate_memory(s).voxels, occupancy + grid + 2 * mips + fragments + kept);
  EXPECT_EQ(estimate_memory(s).voxels, 845792u);
  // Isotropic mips (74896 B) are smaller than the grid: the grid is what is there twice.
  s.vct.anisotropic = false;
  s.vct.bounces = 2;
  EXPECT_EQ(estimate_memory(s).voxels, occupancy + 2 * grid + (16 * n3 + 16 * 585) + fragments + 16 * n3);
  // The CAS model's lo/hi bounds are part of the grid.
  s.vct.reduction = Reduction::CasRgba8;
  EXPECT_EQ(estimate_memory(s).voxels, occupancy + 2 * (grid + 32 * n3) + (16 * n3 + 16 * 585) + fragments + 16 * n3);
}

TEST(MemoryBudget, KeepsEarlierFramesUpTo256MiB) {
  VctSettings v;
  v.grid = 256;  // one frame is 256^3 x 16 B = 256 MiB
  v.bounces = 1;
  EXPECT_FALSE(keeps_multibounce_frames(v));
  v.bounces = 2;
  EXPECT_TRUE(keeps_multibounce_frames(v));
  v.bounces = 3;
  EXPECT_FALSE(keeps_multibounce_frames(v));
  v.grid = 128;  // 32 MiB a frame: eight fit
  v.bounces = 9;
  EXPECT_TRUE(keeps_multibounce_frames(v));
  v.bounces = 10;
  EXPECT_FALSE(keeps_multibounce_frames(v));
}

TEST(MemoryBudget, RefusesWithTheNeededAmount) {
  Settings s;
  s.vct.grid = 512;
  s.vct.anisotropic = true;
  const uint64_t need = estimate_memory(s).total();
  EXPECT_GT(need, 7ull << 30);  // 512^3 anisotropic: ~60 B per voxel
  EXPECT_NO_THROW(check_memory_budget(s, need));
  try {
    check_memory_budget(s, 4ull << 30);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("need about " + format_bytes(need)), std::string::npos) << msg;
    EXPECT_NE(msg.find("has 4.0 GiB"), std::string::npos) << msg;
    EXPECT_NE(msg.find("grid 512^3 anisotropic"), std::string::npos) << msg;
  }
  EXPECT_NO_THROW(check_memory_budget(s, 0));  // unknown machine size: no check
}

TEST(MemoryBudget, ValidateSettingsRefusesHugeImagesOnThisMachine) {
  Settings s;
  s.vct.width = s.vct.height = 16384;
  s.pt.width = s.pt.height = 16384;
  // 16384^2 pixels * (554 + 128) B = 171 GiB: more than any machine these tests run on.
  ASSERT_GT(estimate_memory(s).total(), physical_memory_bytes());
  EXPECT_THROW(validate_settings(s), InputError);
  EXPECT_NO_THROW(validate_settings(Settings{}));
}

// vct validate: the GL frame beside the reference's render, or the two stage sets with the
// comparison, whichever holds more; every per-voxel term by hand (validate's defaults: GPU rule,
// fixed-point reduction, isotropic, one bounce).
TEST(MemoryBudget, ValidateEstimateHandCount) {
  Settings s;
  s.vct.grid = 64;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 50;
  s.pt.width = s.pt.height = 100;
  SceneFootprint scene;
  scene.triangles = 1000;
  scene.texture_bytes = 4096;
  scene.alpha_tested = false;
  const ValidateMemoryEstimate e = estimate_validate_memory(s, scene);
  const uint64_t n3 = 64ull * 64 * 64, coarser_mips = 16 * 37449;
  // A frame's shared stages: radiance 16 B + fragments 4 B per voxel, the coarser mip levels.
  const uint64_t shared = 20 * n3 + coarser_mips;
  EXPECT_EQ(e.gl_frame, shared + 16 * n3);  // + the mips' base level the re-trace reads
  // Both sets: the shared stages twice, and the reference's slack, exactness, occupancy tie,
  // conservative occupancy and hole map (4 B each).
  EXPECT_EQ(e.stage_sets, 2 * shared + 20 * n3);
  EXPECT_EQ(e.judge_scratch, 12 * n3);
  EXPECT_EQ(e.scene_kept, 160u * 1000 + 2 * 4096);  // the scene twice: as loaded and as exposed
  EXPECT_EQ(e.ref.total(), estimate_memory(s, scene).total());
  EXPECT_EQ(e.during_ref(), e.ref.total() + (60ull << 20) + e.gl_frame);
  EXPECT_EQ(e.during_checks(), e.ref.baseline + e.scene_kept + e.ref.images + e.ref.path_tracer + (150ull << 20) +
                                   e.gl_frame + e.stage_sets + e.judge_scratch);
  EXPECT_EQ(e.total(), std::max(e.during_ref(), e.during_checks()));
  // The re-judgement of voxel.radiance on GL's own shadow maps injects the voxels again.
  EXPECT_EQ(e.with_reinjection(), std::max(e.total(), e.during_checks() + e.ref.voxels));
  // Without GL only the reference's terms: no GL frame, one set, no comparison.
  const ValidateMemoryEstimate ref_only = estimate_validate_memory(s, scene, false);
  EXPECT_EQ(ref_only.gl_frame, 0u);
  EXPECT_EQ(ref_only.stage_sets, shared + 20 * n3);
  EXPECT_EQ(ref_only.judge_scratch, 0u);
  EXPECT_EQ(ref_only.with_reinjection(), ref_only.total());
  // CAS keeps its two RGBA float bounds as reference stages.
  s.vct.reduction = Reduction::CasRgba8;
  EXPECT_EQ(estimate_validate_memory(s, scene).stage_sets, 2 * shared + 52 * n3);
  // The warning names both phases.
  testing::internal::CaptureStderr();
  EXPECT_TRUE(warn_if_memory_short(e, "vct validate", 1 << 20));
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("vct validate: warning: this run needs about"), std::string::npos) << warning;
  EXPECT_NE(warning.find("while the stage sets are compared"), std::string::npos) << warning;
  testing::internal::CaptureStderr();
  EXPECT_TRUE(warn_if_memory_short(e, "vct validate", e.total()));  // the re-injection may need more
  EXPECT_NE(testing::internal::GetCapturedStderr().find("re-judged on GL's own shadow maps"), std::string::npos);
  EXPECT_FALSE(warn_if_memory_short(e, "vct validate", e.with_reinjection()));
}

TEST(MemoryBudget, FormatsBytes) {
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(300ull << 20), "300.0 MiB");
  EXPECT_EQ(format_bytes(3ull << 30), "3.0 GiB");
}

}  // namespace
}  // namespace vct
