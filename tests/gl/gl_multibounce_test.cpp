// Temporal multibounce on GL against the CPU reference.
#include "gl_test_util.h"
#include "stages/pipeline.h"

namespace vct::gl::test {

// Temporal multibounce: frame b re-injects restitution x albedo x the diffuse cones of frame b-1
// (level >= 1); the energy after each frame follows the CPU's within the per-frame bounds above.
TEST(GlMultibounce, EnergyPerFrameMatchesTheCpu) {
  VCT_REQUIRE_GL();
  Settings s = small_settings();
  s.vct.bounces = 3;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  const FrameResult r = render_ref_frame(cornell_box(), s);
  ASSERT_EQ(g.multibounce_energy.size(), 3u);
  ASSERT_EQ(r.multibounce_energy.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    std::printf("[gl vs ref] multibounce frame %zu energy: gl %.6g ref %.6g\n", i, g.multibounce_energy[i],
                r.multibounce_energy[i]);
    EXPECT_NEAR(g.multibounce_energy[i], r.multibounce_energy[i], 0.005 * r.multibounce_energy[i]);
  }
  EXPECT_GT(g.multibounce_energy[1], g.multibounce_energy[0]);  // bounces add light
}
}  // namespace vct::gl::test
