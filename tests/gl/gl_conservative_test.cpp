// The GL conservative voxelization modes (settings.conservative_raster; docs/gl_backend.md,
// "Conservative voxelization") against the CPU's exact triangle-box voxelizer, judged as
// `vct compare --scene` judges them (compare/conservative_occupancy.h): the geometry-shader mode on
// two small scenes (no missing voxel, no extra beyond its bound, voxel radiance within its model),
// a deliberate fault under it caught, and the hardware modes refused with exit-3 semantics where
// the driver lacks the extension (llvmpipe has neither).
#include <cstdio>

#include "compare/conservative_occupancy.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl/gl_facts.h"
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

Settings conservative_settings(ConservativeRaster mode) {
  Settings s = small_settings(32, 32);  // grid 32; 32^2 pixels: the cones are not what is tested
  s.vct.voxelizer = Voxelizer::Conservative;  // the reference: the exact set
  s.vct.conservative_raster = mode;
  s.vct.msaa_samples = 1;
  return s;
}

const cmp::StageVerdict& stage(const cmp::Report& rep, const std::string& name) {
  for (const cmp::StageVerdict& v : rep.stages)
    if (v.stage == name) return v;
  ADD_FAILURE() << "no stage " << name;
  return rep.stages.front();
}

cmp::Report judge(GlContext& ctx, const Scene& scene, const std::string& fault = "") {
  const Settings s = conservative_settings(ConservativeRaster::GeometryShader);
  const FrameResult gl = render_gl_frame(ctx, scene, s, {"", fault});
  EXPECT_EQ(gl.facts.conservative_mode, "gs");
  const FrameResult ref = render_ref_frame(scene, s);
  const cmp::StageSet ref_set = cmp::stage_set_from_frame(ref, s.vct), gl_set = cmp::stage_set_from_frame(gl, s.vct);
  cmp::Report rep = cmp::compare_stage_sets(ref_set, gl_set);
  cmp::judge_conservative_mode(rep, ref_set, gl_set, &scene, 10);
  const cmp::StageVerdict& occ = stage(rep, "voxel.occupancy");
  std::printf("  %s gs%s: %s %s; radiance %s: %s\n", scene.source.c_str(), fault.empty() ? "" : (" + " + fault).c_str(),
              cmp::to_string(occ.verdict).c_str(), occ.note.c_str(),
              cmp::to_string(stage(rep, "voxel.radiance").verdict).c_str(), stage(rep, "voxel.radiance").note.c_str());
  return rep;
}

void expect_conservative(const cmp::Report& rep) {
  const cmp::StageVerdict& occ = stage(rep, "voxel.occupancy");
  EXPECT_EQ(occ.model, "conservative-superset");
  EXPECT_NE(occ.verdict, cmp::Verdict::Fail) << occ.note;
  EXPECT_EQ(occ.extra["missing"].get<size_t>(), 0u) << occ.note;
  EXPECT_NE(stage(rep, "voxel.radiance").verdict, cmp::Verdict::Fail) << stage(rep, "voxel.radiance").note;
}

TEST(GlConservative, GeometryShaderModeIsTheExactSetOnTheCornellBox) {
  VCT_REQUIRE_GL();
  expect_conservative(judge(*ctx, cornell_box()));
}

TEST(GlConservative, GeometryShaderModeIsTheExactSetOnTinyTriangles) {
  VCT_REQUIRE_GL();
  static const Scene tiny = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/tiny_triangles.gltf");
  expect_conservative(judge(*ctx, tiny));
}

TEST(GlConservative, HalfTexelFaultUnderTheGeometryShaderModeFailsOccupancy) {
  VCT_REQUIRE_GL();
  const cmp::Report rep = judge(*ctx, cornell_box(), "half_texel");
  EXPECT_EQ(rep.first_failing(), "voxel.occupancy") << failing_stages(rep);
}

TEST(GlConservative, HardwareModeWithoutTheExtensionIsAnEnvironmentError) {
  VCT_REQUIRE_GL();
  const std::vector<std::string> ext = gl_extensions();
  const bool has_nv = std::find(ext.begin(), ext.end(), "GL_NV_conservative_raster") != ext.end();
  if (has_nv) GTEST_SKIP() << "this driver has GL_NV_conservative_raster";
  try {
    render_gl_frame(*ctx, cornell_box(), conservative_settings(ConservativeRaster::Nv));
    ADD_FAILURE() << "no EnvironmentError";
  } catch (const EnvironmentError& e) {
    EXPECT_NE(std::string(e.what()).find("GL_NV_conservative_raster"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vct::gl::test
