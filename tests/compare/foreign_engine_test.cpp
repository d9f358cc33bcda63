// Issue 21's "synthetic foreign engine": the reference frame of the built-in Cornell box,
// post-processed into an engine with other conventions -- a racy binary16 running mean that loses
// updates (stages/running_mean.h) and mips scaled by 1.9 per level (compare/conventions.h) -- and
// judged both ways: declared conventions pass (or only the declared mip deviation fails, at
// mip.iso.1), a real fault under them still fails at its stage, and undeclared conventions fail.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "compare/stage_compare.h"
#include "core/error.h"
#include "find_verdict.h"
#include "racy_engine.h"
#include "scene/gltf_loader.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "freedoms/reference_frame.h"
#include "stages/running_mean.h"
#include "stages/voxelize.h"

namespace vct::cmp {
namespace {

struct Fixture {
  Settings s;
  FrameResult frame;
  StageSet ref;
  Volume engine_voxels;  // the racy running mean over a subset of each voxel's fragments
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.s.vct.width = x.s.vct.height = 64;
    x.s.vct.grid = 32;
    x.s.vct.shadow_map_size = 256;
    x.s.vct.voxelizer = Voxelizer::GpuEmulation;
    x.s.vct.reduction = Reduction::RunningMeanHalf;
    const Scene scene = load_scene("");
    x.frame = render_ref_frame(scene, x.s);
    x.ref = stage_set_from_frame(x.frame, x.s.vct);
    // The engine: same fragments, but each voxel keeps the running mean of its fragments in
    // reverse order with every third one lost (a racing store overwrote it).
    const Voxelization vox = voxelize_gpu_rule(scene, x.s.vct.grid, x.frame.facts.sample_positions);
    const std::vector<vec3> values = fragment_radiance(scene, vox, x.frame.shadow_maps, x.s.vct);
    x.engine_voxels = test::racy_running_mean(vox, values, x.frame.voxels.radiance);
    return x;
  }();
  return f;
}

// The engine's stage set: its voxels and its iso mips, each level the box filter of the level
// below times `mip_scale`; `reduction` and the conventions as its manifest would declare them.
StageSet engine_set(const Volume& voxels, double mip_scale, const std::string& reduction, bool declare_scale) {
  const Fixture& f = fixture();
  FrameResult e = f.frame;
  e.backend = "engine";
  e.voxels.radiance = voxels;
  e.voxels.cas_lo = e.voxels.cas_hi = Volume();  // the reference's judging aids, not an engine's
  e.mips = build_mips(voxels, false);
  for (size_t l = 1; l < e.mips.iso.size(); ++l) {
    e.mips.iso[l] = downsample_iso(e.mips.iso[l - 1]);
    for (float& v : e.mips.iso[l].data) v = float(double(v) * mip_scale);
  }
  StageSet set = stage_set_from_frame(e, f.s.vct);
  set.reduction = reduction;
  if (declare_scale) set.conventions.mip_scale = mip_scale;
  return set;
}

TEST(ForeignEngine, LostUpdatesDifferFromTheExactMean) {
  // The scenario is not vacuous: the engine's voxels are not the reference's.
  const Fixture& f = fixture();
  size_t differ = 0;
  for (size_t i = 0; i < f.engine_voxels.data.size(); ++i)
    differ += f.engine_voxels.data[i] != f.frame.voxels.radiance.data[i];
  EXPECT_GT(differ, 100u);
}

TEST(ForeignEngine, ReferenceStatesTheIntervalAroundItsExactMean) {
  // Reduction::RunningMeanHalf: the reference keeps the exact mean (binary16), which lies in the
  // interval it states in voxel.cas_lo / cas_hi, for every occupied voxel.
  const VoxelGrid& g = fixture().frame.voxels;
  ASSERT_EQ(g.cas_lo.voxel_count(), g.radiance.voxel_count());
  size_t occupied = 0;
  for (size_t i = 0; i < g.radiance.voxel_count(); ++i) {
    if (g.radiance.data[i * 4 + 3] <= 0.0f) continue;
    ++occupied;
    for (size_t c = 0; c < 3; ++c) {
      ASSERT_LE(g.cas_lo.data[i * 4 + c], g.radiance.data[i * 4 + c]) << i;
      ASSERT_GE(g.cas_hi.data[i * 4 + c], g.radiance.data[i * 4 + c]) << i;
    }
  }
  EXPECT_GT(occupied, 1000u);
}

TEST(ForeignEngine, DeclaredConventionsPass) {
  const Report r = compare_stage_sets(fixture().ref, engine_set(fixture().engine_voxels, 1.0, "running_mean", false));
  EXPECT_NE(test::find(r, "voxel.radiance").verdict, Verdict::Fail) << test::find(r, "voxel.radiance").note;
  EXPECT_EQ(test::find(r, "voxel.radiance").model, "running-mean-half-interval");
  EXPECT_NE(r.overall(), Verdict::Fail) << r.first_failing();
}

TEST(ForeignEngine, UndeclaredRunningMeanFailsAtVoxelRadiance) {
  const Report r = compare_stage_sets(fixture().ref, engine_set(fixture().engine_voxels, 1.0, "exact_mean", false));
  EXPECT_EQ(r.first_failing(), "voxel.radiance");
}

TEST(ForeignEngine, VoxelFaultUnderTheDeclaredReductionFails) {
  Volume bad = fixture().engine_voxels;
  // One in 50 occupied voxels off by 10 % (a wrong weight): outside [min, max] of its fragments.
  size_t occupied = 0;
  for (size_t i = 0; i < bad.voxel_count(); ++i)
    if (bad.data[i * 4 + 3] > 0.0f && occupied++ % 50 == 0)
      for (int c = 0; c < 3; ++c) bad.data[i * 4 + size_t(c)] = bad.data[i * 4 + size_t(c)] * 1.1f + 0.01f;
  const Report r = compare_stage_sets(fixture().ref, engine_set(bad, 1.0, "running_mean", false));
  EXPECT_EQ(r.first_failing(), "voxel.radiance");
}

TEST(ForeignEngine, DeclaredMipScaleStillFailsAtMipIso1AndIsExplained) {
  const Report r = compare_stage_sets(fixture().ref, engine_set(fixture().engine_voxels, 1.9, "running_mean", true));
  EXPECT_EQ(r.first_failing(), "mip.iso.1");
  const StageVerdict& m1 = test::find(r, "mip.iso.1");
  EXPECT_EQ(m1.extra.value("explained_by_declared_mip_scale", false), true) << m1.note;
  EXPECT_EQ(m1.extra.value("declared_mip_scale", 0.0), 1.9);
}

TEST(ForeignEngine, UndeclaredMipScaleFailsWithoutExplanation) {
  const Report r = compare_stage_sets(fixture().ref, engine_set(fixture().engine_voxels, 1.9, "running_mean", false));
  EXPECT_EQ(r.first_failing(), "mip.iso.1");
  EXPECT_FALSE(test::find(r, "mip.iso.1").extra.contains("declared_mip_scale"));
}

TEST(ForeignEngine, MipScaleOtherThanDeclaredIsNotExplained) {
  // The engine scales by 2.2 but declares 1.9: the declared deviation does not cover it.
  StageSet e = engine_set(fixture().engine_voxels, 2.2, "running_mean", false);
  e.conventions.mip_scale = 1.9;
  const Report r = compare_stage_sets(fixture().ref, e);
  EXPECT_EQ(r.first_failing(), "mip.iso.1");
  EXPECT_EQ(test::find(r, "mip.iso.1").extra.value("explained_by_declared_mip_scale", true), false);
}

// The engine's spot frustum (issue 21's: 110 degrees, near 0.01): its shadow map, judged against a
// reference that keeps the oracle's own frustum, fails at shadow_map.0; against a reference
// rendered with the same settings (the engine's manifest "settings"), it passes.
TEST(ForeignEngine, ShadowFrustumFailsUndeclaredAndPassesReproduced) {
  const Fixture& f = fixture();
  Settings engine = f.s;
  engine.vct.shadow_fov_deg = 110.0f;
  engine.vct.shadow_near = 0.01f;
  const Scene scene = load_scene("");
  const FrameResult ef = render_ref_frame(scene, engine);
  StageSet e = stage_set_from_frame(ef, engine.vct);
  e.backend = "engine";
  // Only the shadow map comes from the engine here: the rest of the frame is judged elsewhere.
  StageSet shadow_only;
  shadow_only.backend = "engine";
  shadow_only.images["shadow_map.0"] = e.images.at("shadow_map.0");
  const Report undeclared = compare_stage_sets(f.ref, shadow_only);
  EXPECT_EQ(undeclared.first_failing(), "shadow_map.0");
  StageSet reproduced = stage_set_from_frame(render_ref_frame(scene, engine), engine.vct);
  const Report declared = compare_stage_sets(reproduced, shadow_only);
  EXPECT_EQ(test::find(declared, "shadow_map.0").verdict, Verdict::Pass);
}

TEST(ForeignEngine, ConventionsRoundTripThroughTheManifest) {
  StageSet e = engine_set(fixture().engine_voxels, 1.9, "running_mean", true);
  const std::string dir = (std::filesystem::temp_directory_path() / "vct_foreign_engine_test").string();
  std::filesystem::remove_all(dir);
  write_stage_set(dir, e);
  const StageSet back = read_stage_set(dir);
  EXPECT_EQ(back.conventions.mip_scale, 1.9);
  EXPECT_EQ(back.reduction, "running_mean");
  std::filesystem::remove_all(dir);
}

TEST(ForeignEngine, UnknownConventionIsBadInput) {
  EXPECT_THROW(read_conventions("m.json", nlohmann::json{{"mip_scael", 1.9}}), InputError);
  EXPECT_THROW(read_conventions("m.json", nlohmann::json{{"mip_scale", -1}}), InputError);
  EXPECT_THROW(read_conventions("m.json", nlohmann::json::array()), InputError);
  EXPECT_EQ(read_conventions("m.json", nlohmann::json{{"mip_scale", 1.9}}).mip_scale, 1.9);
}

}  // namespace
}  // namespace vct::cmp

namespace vct::cmp {
namespace {
// The engine's PCF (issue 21): a synthetic engine with GL LINEAR compare on a shadow sampler and
// taps at +-1/3 and +-1 texel on both axes. Not gidemo's own taps: its loops (voxelize.frag,
// voxelcone.frag shadow()) give off-centre offsets i/n*2-1 = {-1,-1/3,+1/3} (n = 3) and
// {-1,-1/2,0,+1/2} (n = 4), added before the projective divide so they scale with 1/w. Its frame is the reference rendered with those settings; undeclared
// (judged by a reference that runs the oracle's 3x3 nearest PCF) it fails where the taps act --
// light injection (voxel.radiance), with image.direct's shadow edges beyond the bound -- with the shadow map itself passing; declared (its manifest
// "settings" carry shadow_compare and pcf_taps, so the reference reproduces them) it passes; and a
// real fault under the declared PCF still fails at voxel.radiance.
constexpr const char* kGidemoTaps =
    "-1,-1 -0.3333333,-1 0.3333333,-1 1,-1 -1,-0.3333333 -0.3333333,-0.3333333 0.3333333,-0.3333333 1,-0.3333333 "
    "-1,0.3333333 -0.3333333,0.3333333 0.3333333,0.3333333 1,0.3333333 -1,1 -0.3333333,1 0.3333333,1 1,1";

Settings engine_pcf_settings() {
  Settings s = fixture().s;
  s.vct.shadow_compare = ShadowCompare::Linear;
  s.vct.pcf_taps = kGidemoTaps;
  s.vct.reduction = Reduction::ExactMean;
  return s;
}

struct PcfEngine {
  StageSet engine;      // what the engine dumps
  StageSet reproduced;  // the reference under the engine's declared settings
};

const PcfEngine& pcf_engine() {
  static const PcfEngine p = [] {
    PcfEngine x;
    const Settings s = engine_pcf_settings();
    const FrameResult f = render_ref_frame(load_scene(""), s);
    x.reproduced = stage_set_from_frame(f, s.vct);
    FrameResult e = f;
    e.backend = "engine";
    x.engine = stage_set_from_frame(e, s.vct);
    return x;
  }();
  return p;
}

StageSet oracle_default_reference() {
  Settings s = fixture().s;
  s.vct.reduction = Reduction::ExactMean;
  return stage_set_from_frame(render_ref_frame(load_scene(""), s), s.vct);
}

TEST(ForeignEngine, EnginePcfUndeclaredFailsWhereTheTapsAct) {
  // The map itself is the oracle's; light injection (voxel.radiance) fails, and image.direct shows
  // the taps at the shadow's edges. Since the normal offset (docs/pipeline.md) neither side has
  // acne, so the two kernels differ only at edges: on image.direct 34 of 1 638 edge pixels, under
  // the 2.5 % edge share (it failed first while the constant bias alone left acne to differ on).
  const Report r = compare_stage_sets(oracle_default_reference(), pcf_engine().engine);
  EXPECT_EQ(test::find(r, "shadow_map.0").verdict, Verdict::Pass);
  EXPECT_EQ(r.first_failing(), "voxel.radiance") << test::find(r, "image.direct").note;
  EXPECT_GT(test::find(r, "image.direct").out_of_bound, 20u) << test::find(r, "image.direct").note;
}

TEST(ForeignEngine, EnginePcfDeclaredPasses) {
  const Report r = compare_stage_sets(pcf_engine().reproduced, pcf_engine().engine);
  EXPECT_NE(r.overall(), Verdict::Fail) << r.first_failing();
}

TEST(ForeignEngine, VoxelFaultUnderTheDeclaredPcfFails) {
  StageSet bad = pcf_engine().engine;
  Volume& v = bad.volumes.at("voxel.radiance");
  size_t occupied = 0;
  for (size_t i = 0; i < v.voxel_count(); ++i)
    if (v.data[i * 4 + 3] > 0.0f && occupied++ % 50 == 0)
      for (int c = 0; c < 3; ++c) v.data[i * 4 + size_t(c)] = v.data[i * 4 + size_t(c)] * 1.1f + 0.01f;
  const Report r = compare_stage_sets(pcf_engine().reproduced, bad);
  EXPECT_EQ(r.first_failing(), "voxel.radiance");
}

TEST(ForeignEngine, EnginePcfRoundTripsThroughTheManifestSettings) {
  const std::string dir = (std::filesystem::temp_directory_path() / "vct_foreign_engine_pcf_test").string();
  std::filesystem::remove_all(dir);
  StageSet copy = pcf_engine().engine;
  write_stage_set(dir, copy);
  const StageSet back = read_stage_set(dir);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(back.settings.value("pcf_taps", ""), kGidemoTaps);
  EXPECT_EQ(back.settings.value("shadow_compare", ""), "linear");
}
}  // namespace
}  // namespace vct::cmp
