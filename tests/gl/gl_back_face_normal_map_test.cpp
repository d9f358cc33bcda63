// A normal-mapped triangle seen from behind: GL turns the whole tangent frame as the reference
// negates the shading normal (gl/shaders/gbuffer.frag, ref/stages/gbuffer.cpp). Found by the
// false-alarm hunt (scenes/regressions/seed-66-small): GL flipped only the normal, which mirrors
// a tangent-direction tilt of the map (a texel tilted along the bitangent agreed, one along the
// tangent did not).
#include <cstdio>

#include "compare/judge.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

TEST(GlBackFaceNormalMap, TheBackFaceShadingNormalIsTheReferences) {
  VCT_REQUIRE_GL();
  const std::string dir = std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-66-small/";
  const Scene scene = load_gltf_file(dir + "scene.gltf");
  Settings s = small_settings(16, 15);
  s.vct.shadow_map_size = 64;
  const FrameResult ref = render_ref_frame(scene, s);
  const FrameResult gl = render_gl_frame(*ctx, scene, s);
  // The camera sees the triangle's back face (the case's point: scenes/regressions/seed-66-small).
  size_t covered = 0;
  for (float c : ref.gbuffer.coverage.data) covered += c > 0.0f;
  ASSERT_GT(covered, 0u);
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
  const cmp::Report rep = cmp::judge(cmp::stage_set_from_frame(ref, s.vct), gl_set, {&scene, &gl, &s.vct});
  for (const cmp::StageVerdict& v : rep.stages)
    if (v.stage == "gbuffer.normal") {
      std::printf("  back-face normal map: %zu covered pixels; gbuffer.normal %s (%s)\n", covered,
                  cmp::to_string(v.verdict).c_str(), v.note.c_str());
      EXPECT_NE(v.verdict, cmp::Verdict::Fail);
      EXPECT_EQ(v.out_of_bound, 0u);
    }
}

}  // namespace
}  // namespace vct::gl::test
