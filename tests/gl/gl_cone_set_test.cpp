// A non-seed diffuse cone set (9 cones tilted 60 degrees, rotated per pixel) on GL against the
// CPU: both read the same host-computed block (sh::DiffuseConeBlock), so the cone directions and
// weights agree by construction and only the marching mechanism may differ.
#include <cstdio>

#include "gl_test_util.h"
#include "stages/indirect_pass.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

Settings nine_cones(int grid, int size) {
  Settings s = small_settings(grid, size);
  s.vct.diffuse_cone_count = 9;
  s.vct.diffuse_cone_tilt_deg = 60.0f;
  return s;
}

}  // namespace

TEST(GlConeSet, NineConesAtSixtyDegreesMatchTheCpuOnTheSameInputs) {
  VCT_REQUIRE_GL();
  Settings s = nine_cones(64, 64);
  s.vct.random_rotation = true;
  s.vct.frame = 5;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  // The CPU's marcher on GL's own G-buffer and mips (as GlCrossBackend.ConeTracingOnTheSameInputs).
  const IndirectImages cpu = trace_indirect(cornell_box(), g.gbuffer, g.mips, s.vct);
  ASSERT_EQ(cpu.diffuse_cones.size(), 9u);
  double diff = 0.0, total = 0.0, worst = 0.0;
  size_t n = 0;
  for (int y = 0; y < cpu.diffuse.height; ++y)
    for (int x = 0; x < cpu.diffuse.width; ++x) {
      if (g.gbuffer.coverage.at(x, y, 0) <= 0.0f) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(g.images.indirect_diffuse.at(x, y, c)) - double(cpu.diffuse.at(x, y, c)));
        diff += d;
        total += std::abs(double(cpu.diffuse.at(x, y, c)));
        worst = std::max(worst, d);
        ++n;
      }
    }
  std::printf("[gl vs ref] 9 cones at 60 deg: mean diff %.3g (ref mean %.3g), max %.3g over %zu samples\n",
              diff / double(n), total / double(n), worst, n);
  ASSERT_GT(n, 1000u);
  EXPECT_GT(total, 0.0);
  EXPECT_LE(diff, 0.01 * total);  // the bound of the seed set's cross-backend cone test
}

TEST(GlConeSet, MultibounceWithNineConesFollowsTheCpu) {
  VCT_REQUIRE_GL();
  // The bounce cones are traced in the voxelization shader: the same block reaches it.
  Settings s = nine_cones(32, 64);
  s.vct.bounces = 2;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  const FrameResult r = render_ref_frame(cornell_box(), s);
  ASSERT_EQ(g.multibounce_energy.size(), 2u);
  ASSERT_EQ(r.multibounce_energy.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    std::printf("[gl vs ref] 9 cones, multibounce frame %zu energy: gl %.6g ref %.6g\n", i, g.multibounce_energy[i],
                r.multibounce_energy[i]);
    EXPECT_NEAR(g.multibounce_energy[i], r.multibounce_energy[i], 0.005 * r.multibounce_energy[i]);
  }
  EXPECT_GT(g.multibounce_energy[1], g.multibounce_energy[0]);
}

}  // namespace vct::gl::test
