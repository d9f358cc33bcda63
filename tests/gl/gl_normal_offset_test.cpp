// Normal-offset shadow bias on GL (gl/shaders/lights.glsl, docs/pipeline.md "Normal offset"): the
// lamp-near-a-wall case of issue 35 is lit everywhere, as in the reference, and `vct validate`'s
// judge passes GL against the reference on it with and without the offset.
#include <cstdio>

#include "../ref/lamp_near_a_wall.h"
#include "compare/judge.h"
#include "compare/stage_set.h"
#include "freedoms/reference_frame.h"
#include "gl_test_util.h"

namespace vct::gl::test {
namespace {

TEST(GlNormalOffset, LampNearAWallIsLitEverywhereAndValidates) {
  VCT_REQUIRE_GL();
  const Scene scene = vct::test::lamp_near_a_wall();
  for (const float offset : {0.0f, 1.0f}) {
    Settings s = small_settings(32, 64);
    s.vct.shadow_map_size = 1024;  // validate's
    s.vct.shadow_normal_offset = offset;
    const FrameResult gl = render_gl_frame(*ctx, scene, s);
    const FrameResult ref = render_ref_frame(scene, s);
    const double lit_gl = vct::test::lit_fraction(scene, s.vct, gl.gbuffer, gl.images.direct);
    const double lit_ref = vct::test::lit_fraction(scene, s.vct, ref.gbuffer, ref.images.direct);
    const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
    const cmp::Report rep = cmp::judge(cmp::stage_set_from_frame(ref, s.vct), gl_set, {&scene, &gl, &s.vct});
    std::printf("  shadow_normal_offset %.0f: lit %.4f of the wall on GL, %.4f in the reference; first failing '%s'\n",
                double(offset), lit_gl, lit_ref, rep.first_failing().c_str());
    for (const auto& st : rep.stages)
      if (st.verdict != cmp::Verdict::Pass) std::printf("    %-24s %-5s %s\n", st.stage.c_str(), cmp::to_string(st.verdict).c_str(), st.note.c_str());
    EXPECT_EQ(rep.first_failing(), "") << "failing stages: " << failing_stages(rep);
    if (offset > 0.0f) {
      EXPECT_EQ(lit_gl, 1.0);
      EXPECT_EQ(lit_ref, 1.0);
    } else {
      EXPECT_LT(lit_gl, 0.9);  // the acne the offset removes
    }
  }
}

}  // namespace
}  // namespace vct::gl::test
