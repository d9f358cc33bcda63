// indirect_diffuse_gain (issue 21: an engine's gain on its indirect diffuse, the source design's
// u_restitution) on GL: indirect.frag multiplies the diffuse cones' result by the uniform
// u_indirect_diffuse_gain, set from the settings table. GL's image.indirect_diffuse is judged
// against the CPU's trace on GL's own G-buffer and mips with the same gain (the bound of the
// cross-backend cone tests, 1 % of the summed |radiance|), and the gain must matter by far more.
#include <cmath>

#include "gl_test_util.h"
#include "stages/indirect_pass.h"
#include "stages/pipeline.h"

namespace vct::gl::test {
namespace {

double l1(const Image& a, const Image& b, const Image& coverage, double* total) {
  double d = 0.0;
  *total = 0.0;
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      if (coverage.at(x, y, 0) <= 0.0f) continue;
      for (int c = 0; c < 3; ++c) {
        d += std::abs(double(a.at(x, y, c)) - double(b.at(x, y, c)));
        *total += std::abs(double(b.at(x, y, c)));
      }
    }
  return d;
}

}  // namespace

TEST(GlIndirectGain, GainedDiffuseMatchesTheCpuOnTheSameInputs) {
  VCT_REQUIRE_GL();
  Settings s = small_settings(64, 64);
  s.vct.indirect_diffuse_gain = 0.15f;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  const IndirectImages cpu = trace_indirect(cornell_box(), g.gbuffer, g.mips, s.vct);
  Settings ungained = s;
  ungained.vct.indirect_diffuse_gain = 1.0f;
  const IndirectImages cpu1 = trace_indirect(cornell_box(), g.gbuffer, g.mips, ungained.vct);
  double total = 0.0, total1 = 0.0;
  const double diff = l1(g.images.indirect_diffuse, cpu.diffuse, g.gbuffer.coverage, &total);
  const double diff1 = l1(g.images.indirect_diffuse, cpu1.diffuse, g.gbuffer.coverage, &total1);
  std::printf("[gl vs ref] indirect_diffuse_gain 0.15: L1 %.3g of %.3g; against the ungained CPU %.3g\n", diff,
              total, diff1);
  ASSERT_GT(total, 0.0);
  EXPECT_LE(diff, 0.01 * total);
  EXPECT_GT(diff1, 0.5 * total1);  // 0.85 of the ungained light: GL ignoring the uniform fails above
}

}  // namespace vct::gl::test
