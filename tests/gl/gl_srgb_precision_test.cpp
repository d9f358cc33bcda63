// The sRGB decode's precision on llvmpipe (core/precision.h, srgb-decode; docs/compare.md,
// "Precision table"): the two regression cases of issue 34 kind 1 (scenes/regressions/seed-9-small:
// emission from a dark sRGB texture, no light; seed-114-small: a dark sRGB base colour under a sun)
// failed voxel.radiance on a correct GL before the voxel shading slack carried the decode's half
// step; they pass now, and the GL fault srgb_decode_step (one step high, twice the precision) fails
// voxel.radiance on seed-9.
#include <cstdio>

#include "compare/judge.h"
#include "freedoms/reference_frame.h"
#include "gl_test_util.h"

namespace vct::gl::test {
namespace {

Settings case_settings(int height) {  // the cases' settings.json: 8 x height, grid 16, map 64
  Settings s;
  s.vct.width = 8;
  s.vct.height = height;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 64;
  s.vct.voxelizer = Voxelizer::GpuEmulation;  // as vct validate runs GL (the sample rule)
  s.threads = 2;
  return s;
}

cmp::Report judge_case(GlContext& ctx, const std::string& stem, const Settings& s, const std::string& fault = "") {
  const Scene scene = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/" + stem + "/scene.gltf");
  const FrameResult gl = render_gl_frame(ctx, scene, s, {"", fault});
  const FrameResult ref = render_ref_frame(scene, s, gl.facts.sample_positions);
  const cmp::Report rep =
      cmp::judge(cmp::stage_set_from_frame(ref, s.vct), cmp::stage_set_from_frame(gl, s.vct), {&scene, &gl, &s.vct});
  for (const cmp::StageVerdict& v : rep.stages)
    if (v.stage == "voxel.radiance")
      std::printf("  %s%s%s: voxel.radiance %s: %s\n", stem.c_str(), fault.empty() ? "" : " fault ", fault.c_str(),
                  to_string(v.verdict).c_str(), v.note.c_str());
  return rep;
}

TEST(GlSrgbPrecision, DarkSrgbTexturesPassInTheVoxels) {
  VCT_REQUIRE_GL();
  EXPECT_EQ(judge_case(*ctx, "seed-9-small", case_settings(14)).first_failing(), "");
  EXPECT_EQ(judge_case(*ctx, "seed-114-small", case_settings(12)).first_failing(), "");
}

TEST(GlSrgbPrecision, DecodingOneStepHighFailsTheVoxels) {
  VCT_REQUIRE_GL();
  const cmp::Report rep = judge_case(*ctx, "seed-9-small", case_settings(14), "srgb_decode_step");
  EXPECT_EQ(rep.first_failing(), "voxel.radiance") << failing_stages(rep);
}

}  // namespace
}  // namespace vct::gl::test
