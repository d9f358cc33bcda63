// Issue 17's artifact fixes on GL against the CPU reference, judged as `vct validate` judges them
// (cone stages on the GL frame's own inputs): solid voxelization, surface thickening and the
// opacity step correction each pass on the Cornell box at 32^3 / 64^2, change what they should, and
// a GL frame that leaves the variant out fails the stage where the variant lives.
#include <cstdio>

#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

// The judgement of `gl` (rendered with whatever settings) against the reference rendered with `s`.
cmp::Report judge(const FrameResult& ref, const FrameResult& gl, const VctSettings& s) {
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s);
  cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s), gl_set);
  cmp::judge_cones_on_test_inputs(rep, cornell_box(), gl, s, gl_set);
  return rep;
}

const cmp::StageVerdict& verdict_of(const cmp::Report& rep, const std::string& stage) {
  for (const auto& st : rep.stages)
    if (st.stage == stage) return st;
  ADD_FAILURE() << "no stage " << stage;
  return rep.stages.front();
}

size_t opaque_voxels(const FrameResult& f) {
  size_t n = 0;
  const Volume& v = f.voxels.radiance;
  for (size_t i = 0; i < v.voxel_count(); ++i) n += v.data[i * 4 + 3] > 0.0f;
  return n;
}

struct VariantRun {
  FrameResult ref, gl, gl_plain;  // gl_plain: the GL frame without the variant
  Settings s;
};

VariantRun run_variant(GlContext& ctx, void (*set)(VctSettings&)) {
  VariantRun r;
  r.s = small_settings();
  set(r.s.vct);
  r.ref = render_ref_frame(cornell_box(), r.s);
  r.gl = render_gl_frame(ctx, cornell_box(), r.s);
  r.gl_plain = render_gl_frame(ctx, cornell_box(), small_settings());
  return r;
}

void expect_no_failure(const VariantRun& r, const char* name) {
  const cmp::Report rep = judge(r.ref, r.gl, r.s.vct);
  for (const auto& st : rep.stages)
    if (st.stage == "voxel.occupancy" || st.stage == "voxel.radiance" || st.stage.rfind("image.", 0) == 0)
      std::printf("  [%s] %-24s %-5s %s\n", name, st.stage.c_str(), to_string(st.verdict).c_str(), st.note.c_str());
  EXPECT_EQ(rep.first_failing(), "") << name << ": failing stages: " << failing_stages(rep);
}

TEST(GlVariants, SolidVoxelizationFillsTheBoxesLikeTheCpu) {
  VCT_REQUIRE_GL();
  const VariantRun r = run_variant(*ctx, [](VctSettings& v) { v.solid_voxelization = true; });
  // The two boxes are closed: their interiors fill, in both backends, by the same number of voxels.
  const size_t added_gl = opaque_voxels(r.gl) - opaque_voxels(r.gl_plain);
  std::printf("  solid: %zu voxels filled on GL, %zu opaque in ref\n", added_gl, opaque_voxels(r.ref));
  EXPECT_GT(added_gl, 20u);
  expect_no_failure(r, "solid");
  // A GL that does not fill fails voxel.occupancy (the filled voxels have no surface difference
  // on their axis rays to excuse them).
  const cmp::Report missing = judge(r.ref, r.gl_plain, r.s.vct);
  EXPECT_EQ(verdict_of(missing, "voxel.occupancy").verdict, cmp::Verdict::Fail);
}

TEST(GlVariants, SurfaceThickeningAddsTheCpusLayers) {
  VCT_REQUIRE_GL();
  const VariantRun r = run_variant(*ctx, [](VctSettings& v) { v.surface_thickening_voxels = 2; });
  const size_t added_gl = opaque_voxels(r.gl) - opaque_voxels(r.gl_plain);
  std::printf("  thickening 2: %zu voxels added on GL\n", added_gl);
  EXPECT_GT(added_gl, 500u);
  expect_no_failure(r, "thickening");
  const cmp::Report missing = judge(r.ref, r.gl_plain, r.s.vct);
  EXPECT_EQ(verdict_of(missing, "voxel.occupancy").verdict, cmp::Verdict::Fail);
}

TEST(GlVariants, OpacityStepCorrectionMatchesTheCpu) {
  VCT_REQUIRE_GL();
  const VariantRun r = run_variant(*ctx, [](VctSettings& v) { v.opacity_step_correction = true; });
  expect_no_failure(r, "step correction");
  // The correction lowers each sample's opacity (quality 0.5: dt/dt0 = 1/2), so cones see further
  // and the indirect light changes; an uncorrected GL marcher fails the indirect image.
  const cmp::Report uncorrected = judge(r.ref, r.gl_plain, r.s.vct);
  EXPECT_EQ(verdict_of(uncorrected, "image.indirect_diffuse").verdict, cmp::Verdict::Fail)
      << "failing stages: " << failing_stages(uncorrected);
}

}  // namespace
}  // namespace vct::gl::test
