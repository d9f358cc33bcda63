// Cone stages judged on the test's own inputs: the reference re-traced on its own frame gives the
// same bytes, and the verdict merge keeps real marcher failures while excusing upstream ties.
#include <gtest/gtest.h>

#include "compare/isolated_stages.h"
#include "scene/gltf_loader.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/multibounce.h"
#include "stages/particles.h"
#include "freedoms/reference_frame.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct::cmp {
namespace {

TEST(IsolatedStages, ReferenceOnItsOwnInputsReproducesItsImages) {
  const Scene scene = load_scene("");
  Settings s;
  s.vct.width = s.vct.height = 32;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  const FrameResult ref = render_ref_frame(scene, s);
  const FrameResult again = reference_on_test_inputs(scene, ref, s.vct);
  EXPECT_EQ(again.images.indirect_diffuse.data, ref.images.indirect_diffuse.data);
  EXPECT_EQ(again.images.indirect_specular.data, ref.images.indirect_specular.data);
  EXPECT_EQ(again.images.final_image.data, ref.images.final_image.data);
  // And it does read the mips it is given: empty voxels give no indirect light.
  FrameResult dark = ref;
  for (Volume& level : dark.mips.iso) std::fill(level.data.begin(), level.data.end(), 0.0f);
  const FrameResult traced = reference_on_test_inputs(scene, dark, s.vct);
  for (float v : traced.images.indirect_diffuse.data) ASSERT_EQ(v, 0.0f);
}

StageVerdict verdict(const std::string& stage, Verdict v) {
  StageVerdict s;
  s.stage = stage;
  s.verdict = v;
  s.note = to_string(v);
  return s;
}

TEST(IsolatedStages, UpstreamTiesWarnButAWrongMarcherStillFails) {
  Report e2e;
  e2e.stages = {verdict("voxel.occupancy", Verdict::Warn), verdict("image.indirect_diffuse", Verdict::Fail),
                verdict("image.indirect_specular", Verdict::Fail), verdict("gbuffer.albedo", Verdict::Fail),
                verdict("image.direct", Verdict::Fail)};
  Report iso;
  iso.stages = {verdict("image.indirect_diffuse", Verdict::Pass), verdict("image.indirect_specular", Verdict::Fail),
                verdict("gbuffer.albedo", Verdict::Pass), verdict("image.direct", Verdict::Pass)};
  apply_isolated_verdicts(e2e, iso, false);
  EXPECT_EQ(e2e.stages[1].verdict, Verdict::Warn);  // ties upstream, marcher right
  EXPECT_EQ(e2e.stages[1].extra["end_to_end"]["verdict"], "fail");
  EXPECT_EQ(e2e.stages[2].verdict, Verdict::Fail);  // marcher wrong on its own inputs
  EXPECT_EQ(e2e.stages[3].verdict, Verdict::Fail);  // not judged on the test's inputs: untouched
  // Direct light is re-shaded on the test's G-buffer and shadow maps (docs/compare.md, "Shading
  // stages on the test's own inputs"): right there, so the end-to-end failure came from upstream.
  EXPECT_EQ(e2e.stages[4].verdict, Verdict::Warn);
  EXPECT_EQ(e2e.first_failing(), "image.indirect_specular");
}

// Multibounce voxels on the test's own bounce input: the reference's frame given to itself gives
// its own last frame back bit for bit, and a test whose last frame added the bounce light 1.5x
// too strongly (on a right bounce input) fails voxel.radiance there, while the same frame
// judged end to end is blamed the same way.
TEST(IsolatedStages, BounceVoxelsOnTheTestsOwnInputReproduceAndCatchAWrongBounce) {
  const Scene scene = load_scene("");
  Settings s;
  s.vct.width = s.vct.height = 32;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  s.vct.bounces = 3;
  const FrameResult ref = render_ref_frame(scene, s);
  ASSERT_EQ(ref.bounce_input.nx, 16);
  const std::optional<VoxelGrid> again = reference_voxels_on_test_inputs(scene, ref, s.vct);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->radiance.data, ref.voxels.radiance.data);
  // One frame and no shadow maps of its own: nothing to judge on.
  FrameResult one = ref;
  one.bounce_input = Volume();
  one.shadow_maps.clear();
  EXPECT_FALSE(reference_voxels_on_test_inputs(scene, one, s.vct).has_value());

  // The faulty test: its last frame's bounce light x 1.5, everything else the reference's.
  VctSettings strong = s.vct;
  strong.restitution *= 1.5f;
  const Voxelization vox = voxelize_gpu_rule(scene, 16, ref.facts.sample_positions);
  const VoxelMips bounce_mips = build_mips(ref.bounce_input, false);  // read by the bounce light
  const BounceLight bounce = make_bounce_light(scene, bounce_mips, strong);
  FrameResult faulty = ref;
  faulty.voxels = inject_and_reduce(scene, vox, render_shadow_maps(scene, s.vct), s.vct, &bounce);
  add_particles_to_voxels(scene, s.vct, faulty.voxels.radiance);
  const StageSet faulty_set = stage_set_from_frame(faulty, s.vct);
  Report rep = compare_stage_sets(stage_set_from_frame(ref, s.vct), faulty_set);
  judge_cones_on_test_inputs(rep, scene, faulty, s.vct, faulty_set);
  const auto radiance = std::find_if(rep.stages.begin(), rep.stages.end(),
                                     [](const StageVerdict& v) { return v.stage == "voxel.radiance"; });
  ASSERT_NE(radiance, rep.stages.end());
  EXPECT_EQ(radiance->verdict, Verdict::Fail) << radiance->note;
  EXPECT_NE(radiance->note.find("the test's own shadow maps and bounce input"), std::string::npos) << radiance->note;
  // The right frame judged the same way passes.
  const StageSet ref_set = stage_set_from_frame(ref, s.vct);
  Report same = compare_stage_sets(ref_set, ref_set);
  judge_cones_on_test_inputs(same, scene, ref, s.vct, ref_set);
  EXPECT_EQ(same.first_failing(), "");
}

}  // namespace
}  // namespace vct::cmp
