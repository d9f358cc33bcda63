// An engine's spot shadow frustum (issue 21; settings shadow_fov_deg / shadow_near / shadow_far)
// is reproduced by both backends: GL renders the map from the same matrix as the CPU, and the
// two maps agree within GlCrossBackend.ShadowMapDepth's bound (2^-14, llvmpipe's plane-equation
// depth), while the matrix differs from the oracle's own rule.
#include <cstdio>

#include "gl_test_util.h"
#include "freedoms/reference_frame.h"
#include "stages/shadow_map.h"

namespace vct::gl::test {
namespace {

TEST(GlShadowConventions, EngineFrustumOnBothBackends) {
  GlContext* ctx = shared_context();
  if (!ctx) GTEST_SKIP() << "no OpenGL 4.5 context";
  Settings s = small_settings();
  s.vct.shadow_fov_deg = 100.0f;
  s.vct.shadow_near = 0.05f;
  const Scene& scene = cornell_box();
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const FrameResult r = render_ref_frame(scene, s);
  ASSERT_EQ(g.shadow_maps.size(), r.shadow_maps.size());
  ASSERT_FALSE(r.shadow_maps.empty());
  for (size_t i = 0; i < r.shadow_maps.size(); ++i) {
    if (scene.lights[i].is_point() || scene.lights[i].is_directional()) continue;
    EXPECT_EQ(g.shadow_maps[i].view_proj, r.shadow_maps[i].view_proj);
    EXPECT_NE(r.shadow_maps[i].view_proj, spot_light_view_proj(scene.lights[i], scene.bounds));
    const Image &gd = g.shadow_maps[i].depth, &rd = r.shadow_maps[i].depth;
    size_t mismatch = 0, both = 0;
    float max_d = 0.0f;
    for (size_t k = 0; k < gd.data.size(); ++k) {
      const bool cg = gd.data[k] < 1.0f, cr = rd.data[k] < 1.0f;
      if (cg != cr) {
        ++mismatch;
        continue;
      }
      if (cg) ++both, max_d = std::max(max_d, std::abs(gd.data[k] - rd.data[k]));
    }
    std::printf("[gl vs ref, engine frustum] map %zu: max depth diff %.3g over %zu texels, %zu coverage mismatches\n",
                i, double(max_d), both, mismatch);
    EXPECT_LE(max_d, 1.0f / 16384.0f);
    EXPECT_LE(mismatch, gd.data.size() / 1000);
    EXPECT_GT(both, gd.data.size() / 10);
  }
}

}  // namespace
}  // namespace vct::gl::test
