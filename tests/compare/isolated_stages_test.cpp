// Cone stages judged on the test's own inputs: the reference re-traced on its own frame gives the
// same bytes, and the verdict merge keeps real marcher failures while excusing upstream ties.
#include <gtest/gtest.h>

#include "compare/isolated_stages.h"
#include "scene/gltf_loader.h"
#include "stages/pipeline.h"

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
                verdict("image.indirect_specular", Verdict::Fail), verdict("image.direct", Verdict::Fail)};
  Report iso;
  iso.stages = {verdict("image.indirect_diffuse", Verdict::Pass), verdict("image.indirect_specular", Verdict::Fail),
                verdict("image.direct", Verdict::Pass)};
  apply_isolated_verdicts(e2e, iso, false);
  EXPECT_EQ(e2e.stages[1].verdict, Verdict::Warn);  // ties upstream, marcher right
  EXPECT_EQ(e2e.stages[1].extra["end_to_end"]["verdict"], "fail");
  EXPECT_EQ(e2e.stages[2].verdict, Verdict::Fail);  // marcher wrong on its own inputs
  EXPECT_EQ(e2e.stages[3].verdict, Verdict::Fail);  // not cone-traced: untouched
  EXPECT_EQ(e2e.first_failing(), "image.indirect_specular");
}

}  // namespace
}  // namespace vct::cmp
