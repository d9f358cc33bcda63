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
  // RGBA float radiance + float fragment count; the freedoms: shading slack, exactness, occupancy
  // tie (a float each) and the fragment count range (two).
  const uint64_t grid = 40 * n3;
  // iso[0] copies the base; levels 1..6 hold 32^3 + 16^3 + ... + 1 = 37449 voxels.
  const uint64_t mips = 16 * n3 + 16 * 37449;
  const uint64_t fragments = 8 * 64 * 64 * 157;  // 8 N^2 fragments, 157 B each (12 of them the kept light)
  EXPECT_EQ(e.voxels, occupancy + grid + mips + fragments);
  EXPECT_EQ(e.voxels, 22520976u);
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

// A loaded scene adds its arrays (44 B per triangle) and decoded texels, and 435 B per triangle
// while it is loaded and rasterized (measured: bench/memory_bench.py); without alpha masks a
// shadow map's ties need no full-map scratch.
TEST(MemoryBudget, SceneTermsFollowTrianglesTexturesAndMasks) {
  Settings s;
  s.vct.grid = 16;  // voxels below either scratch: the larger scratch is what the total counts
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 2048;
  SceneFootprint scene;
  scene.triangles = 1000;  // each meets at least one voxel: 1000 fragments (fragment_count)
  scene.texture_bytes = 4ull * 1024 * 1024;
  const MemoryEstimate masked = estimate_memory(s, scene);
  EXPECT_EQ(masked.scene, 44000ull + 4194304ull);
  EXPECT_EQ(masked.raster_scratch, 2048ull * 2048 * 82 + 435000);
  scene.alpha_tested = false;
  const MemoryEstimate opaque = estimate_memory(s, scene);
  EXPECT_EQ(opaque.raster_scratch, 100ull * 100 * 60 + 435000);  // the camera's scratch only
  ASSERT_LT(opaque.voxels, opaque.raster_scratch);
  EXPECT_EQ(masked.total() - opaque.total(), 2048ull * 2048 * 82 - 100ull * 100 * 60);
  // Without a scene: no scene term, masks assumed (the estimate validate_settings checks).
  EXPECT_EQ(estimate_memory(s).scene, 0u);
  EXPECT_EQ(estimate_memory(s).raster_scratch, 2048ull * 2048 * 82);
}

// Steiner's formula by hand (core/steiner_count.h): the voxels a triangle meets on average are
// A (|n_x| + |n_y| + |n_z|) + e_x + e_y + e_z + 1, in voxels.
TEST(MemoryBudget, SteinerCountByHand) {
  // Legs of 2 voxels in a z plane: area 2, normal z, extents (2, 2, 0): 2 + 4 + 1 = 7 (one layer
  // in z; in x and y the 2-D Steiner count of a right triangle, area + width + height + 1).
  const SteinerTerms flat = steiner_terms({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  EXPECT_DOUBLE_EQ(flat.projected_area, 2.0);
  EXPECT_DOUBLE_EQ(flat.extent, 4.0);
  EXPECT_DOUBLE_EQ(steiner_voxels(flat, 1, 1), 7.0);
  // Tilted: (1,0,0) x (0,1,1) = (0,-1,1); projections of area 0 + 1/2 + 1/2, extents 1 + 1 + 1.
  const SteinerTerms tilted = steiner_terms({0, 0, 0}, {1, 0, 0}, {0, 1, 1});
  EXPECT_DOUBLE_EQ(tilted.projected_area, 1.0);
  EXPECT_DOUBLE_EQ(tilted.extent, 3.0);
  EXPECT_DOUBLE_EQ(steiner_voxels(tilted, 1, 1), 5.0);
  // Far below a voxel (a heightfield's): barely more than the one voxel it is in.
  const SteinerTerms tiny = steiner_terms({0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0});
  EXPECT_NEAR(steiner_voxels(tiny, 1, 1), 0.005 + 0.2 + 1.0, 1e-12);
  // Sums in units of the volume's edge scale with the grid: the flat triangle is (0.5, 0.5) of a
  // unit cube cut into 4 voxels per edge, and the three together are 7 + 5 + 1.205 voxels.
  const SteinerTerms unit = steiner_terms({0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0});
  EXPECT_DOUBLE_EQ(steiner_voxels(unit, 1, 4), 7.0);
  SceneFootprint scene;
  scene.triangles = 3;
  scene.fragment_terms = {flat.projected_area + tilted.projected_area + tiny.projected_area,
                          flat.extent + tilted.extent + tiny.extent};
  EXPECT_EQ(fragment_count(scene, 1), 14u);  // 13.205, rounded up
  // At grid 64 the same sums (now in units of the edge) are 64^2 x 3.005 + 64 x 7.2 + 3.
  EXPECT_EQ(fragment_count(scene, 64), 12773u);  // 12308.48 + 460.8 + 3 = 12772.28, rounded up
  // Without a scene: a room's 8 N^2.
  EXPECT_EQ(fragment_count(SceneFootprint{}, 64), 8u * 64 * 64);
}

// With particle emitters the particle ties reduce the grid a second time beside the frame:
// radiance (RGBA float) and fragment count again, and the CAS bounds with that model.
TEST(MemoryBudget, ParticleTiesReduceTheGridAgain) {
  Settings s;
  s.vct.grid = 32;
  s.vct.reduction = Reduction::ExactMean;
  SceneFootprint scene;
  scene.triangles = 10;
  const uint64_t without = estimate_memory(s, scene).voxels;
  scene.particles = true;
  EXPECT_EQ(estimate_memory(s, scene).voxels - without, 20ull * 32 * 32 * 32);
  s.vct.particles = false;  // no particles rendered: no ties
  SceneFootprint no_emitters = scene;
  no_emitters.particles = false;
  EXPECT_EQ(estimate_memory(s, scene).voxels, estimate_memory(s, no_emitters).voxels);
  s.vct.particles = true;
  s.vct.reduction = Reduction::CasRgba8;
  scene.particles = false;
  const uint64_t cas = estimate_memory(s, scene).voxels;
  scene.particles = true;
  EXPECT_EQ(estimate_memory(s, scene).voxels - cas, 52ull * 32 * 32 * 32);
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
  const uint64_t grid = 40 * n3;       // RGBA float + fragment count, the freedoms (5 floats)
  // iso[0] copy; the iso pyramid and six directional ones, levels 1..4: 512 + 64 + 8 + 1 = 585.
  const uint64_t mips = 16 * n3 + 7 * 16 * 585;
  const uint64_t fragments = 8 * 16 * 16 * 157;
  const uint64_t kept = 2 * 16 * n3;  // base levels of frames 1 and 2 (RGBA float)
  // The grid with its freedoms (163840 B) outweighs even the anisotropic mips (131056 B): it is
  // what is there twice.
  ASSERT_GT(grid, mips);
  EXPECT_EQ(estimate_memory(s).voxels, occupancy + 2 * grid + mips + fragments + kept);
  EXPECT_EQ(estimate_memory(s).voxels, 960496u);
  // Isotropic mips (74896 B) are smaller still.
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
  // The GL frame read back: those, the mips' base level the re-trace reads, one 50^2 float shadow
  // map and 168 B per pixel (G-buffer 84, frame images 84); its grid (20 B/voxel) moves into its set.
  EXPECT_EQ(e.gl_frame, shared + 16 * n3 + 4 * 2500 + 168 * 10000);
  EXPECT_EQ(e.gl_grid, 20 * n3);
  // Both sets: the shared stages twice, and the reference's slack, exactness, occupancy tie,
  // conservative occupancy and hole map (4 B each) and fragment count range (8 B).
  EXPECT_EQ(e.stage_sets, 2 * shared + 28 * n3);
  EXPECT_EQ(e.judge_scratch, 12 * n3);
  EXPECT_EQ(e.scene_kept, 160u * 1000 + 2 * 4096);  // the scene twice: as loaded and as exposed
  EXPECT_EQ(e.ref.total(), estimate_memory(s, scene).total());
  EXPECT_EQ(e.during_ref(), e.ref.total() + (60ull << 20) + e.gl_frame);
  EXPECT_EQ(e.during_checks(), e.ref.baseline + e.scene_kept + e.ref.images + e.ref.path_tracer + (150ull << 20) +
                                   e.gl_frame - 20 * n3 + e.stage_sets + e.judge_scratch);
  // While GL renders: its own estimate and the scene as loaded (80 B per triangle and the textures).
  EXPECT_EQ(e.gl.total(), estimate_gl_memory(s, scene).total());
  EXPECT_EQ(e.during_gl(), e.gl.total() + 80u * 1000 + 4096);
  EXPECT_EQ(e.total(), std::max({e.during_gl(), e.during_ref(), e.during_checks()}));
  // The re-judgement of voxel.radiance on GL's own shadow maps injects the voxels again.
  // One voxelization's occupancy (4 B), a judged grid with its freedoms (40 B), the radiance kept
  // around the particles (16 B), its 1000 fragments (157 B each), after the judges' scratch is freed.
  EXPECT_EQ(e.reinjection, 60 * n3 + 1000 * 157);
  EXPECT_EQ(e.with_reinjection(), std::max(e.total(), e.during_checks() - e.judge_scratch + e.reinjection));
  // With multibounce it always runs (on GL's own bounce input): the estimate is that phase's.
  Settings bounces = s;
  bounces.vct.bounces = 2;
  const ValidateMemoryEstimate mb = estimate_validate_memory(bounces, scene);
  EXPECT_TRUE(mb.rejudges_radiance);
  EXPECT_EQ(mb.total(), mb.with_reinjection());
  EXPECT_EQ(mb.reinjection, 60 * n3 + 1000 * 157 + 16 * n3 + coarser_mips);  // + the bounce input's mips
  EXPECT_EQ(mb.total(), std::max(mb.phases(), mb.during_checks() - mb.judge_scratch + mb.reinjection));
  EXPECT_FALSE(e.rejudges_radiance);
  // Without GL only the reference's terms: no GL frame, one set, no comparison.
  const ValidateMemoryEstimate ref_only = estimate_validate_memory(s, scene, false);
  EXPECT_EQ(ref_only.gl_frame, 0u);
  EXPECT_EQ(ref_only.during_gl(), 0u);
  EXPECT_EQ(ref_only.stage_sets, shared + 28 * n3);
  EXPECT_EQ(ref_only.judge_scratch, 0u);
  EXPECT_EQ(ref_only.with_reinjection(), ref_only.total());
  // CAS keeps its two RGBA float bounds as reference stages.
  s.vct.reduction = Reduction::CasRgba8;
  EXPECT_EQ(estimate_validate_memory(s, scene).stage_sets, 2 * shared + 60 * n3);
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
  // The scene's fragments by Steiner's formula (core/steiner_count.h): 1000 triangles whose
  // projected areas sum to 0.25 and extents to 3 (units of the volume's edge) meet
  // 0.25 x 64^2 + 3 x 64 + 1000 = 2216 voxels, not 1000 (no sums) at 157 B each.
  const uint64_t voxels_without = estimate_validate_memory(s, scene).ref.voxels;
  scene.fragment_terms = {0.25, 3.0};
  EXPECT_EQ(estimate_validate_memory(s, scene).ref.voxels - voxels_without, (2216u - 1000u) * 157);
}

// vct render --backend gl, by hand: GL's textures, the frame read back, llvmpipe's own and the
// measured bytes per triangle (docs/performance.md, "Validate's memory").
TEST(MemoryBudget, GlEstimateHandCount) {
  Settings s;
  s.vct.grid = 64;
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 50;
  SceneFootprint scene;
  scene.shadow_layers = 2;
  scene.triangles = 1000;
  scene.texture_bytes = 4096;
  const GlMemoryEstimate e = estimate_gl_memory(s, scene);
  const uint64_t n3 = 64ull * 64 * 64, coarser = 37449;
  EXPECT_EQ(e.baseline, (136ull + 88) << 20);  // the process and llvmpipe's own (measured)
  EXPECT_EQ(e.scene, 420u * 1000 + 4096);      // 420 B per triangle (measured) and the texels
  // Sums 4 x 4 B and particle sums 3 x 4 B; two RGBA16F radiance textures with mips; two DEPTH32F
  // shadow layers; per pixel six RGBA32F G-buffer targets and depth (100 B) and eight RGBA32F images.
  EXPECT_EQ(e.textures, 28 * n3 + 2 * 8 * (n3 + coarser) + 4 * 2 * 2500 + 228 * 10000);
  // Read back: radiance and fragments, every iso level, the maps, 168 B per pixel.
  EXPECT_EQ(e.frame, 20 * n3 + 16 * (n3 + coarser) + 4 * 2 * 2500 + 168 * 10000);
  EXPECT_EQ(e.total(), e.baseline + e.scene + e.textures + e.frame);
  // Anisotropic: two sets of six directional pyramids in GL, one read back (RGBA float).
  s.vct.anisotropic = true;
  const GlMemoryEstimate aniso = estimate_gl_memory(s, scene);
  EXPECT_EQ(aniso.textures - e.textures, 2 * 6 * 8 * coarser);
  EXPECT_EQ(aniso.frame - e.frame, 6 * 16 * coarser);
}

TEST(MemoryBudget, FormatsBytes) {
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(300ull << 20), "300.0 MiB");
  EXPECT_EQ(format_bytes(3ull << 30), "3.0 GiB");
}

}  // namespace
}  // namespace vct
