// Cone-traced soft shadows on GL against the CPU reference.
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {

// Soft shadows: visibility from a cone toward the light through the voxels instead of PCF.
TEST(GlSoftShadows, ConeVisibilityMatchesTheCpu) {
  VCT_REQUIRE_GL();
  Settings s = small_settings();
  s.vct.soft_shadows = true;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  const FrameResult r = render_ref_frame(cornell_box(), s);
  ASSERT_FALSE(g.images.soft_shadow.data.empty());
  ASSERT_EQ(g.images.soft_shadow.data.size(), r.images.soft_shadow.data.size());
  double diff = 0.0, total = 0.0, ddiff = 0.0, dtotal = 0.0;
  for (size_t k = 0; k < g.images.soft_shadow.data.size(); ++k) {
    diff += std::abs(double(g.images.soft_shadow.data[k]) - double(r.images.soft_shadow.data[k]));
    total += double(r.images.soft_shadow.data[k]);
  }
  for (size_t k = 0; k < g.images.direct.data.size(); ++k) {
    ddiff += std::abs(double(g.images.direct.data[k]) - double(r.images.direct.data[k]));
    dtotal += double(r.images.direct.data[k]);
  }
  std::printf("[gl vs ref] soft-shadow visibility relative L1 %.3g, direct (soft) relative L1 %.3g\n", diff / total,
              ddiff / dtotal);
  EXPECT_GT(total, 100.0);
  EXPECT_LE(diff / total, 0.01);
  EXPECT_LE(ddiff / dtotal, 0.01);
}
}  // namespace vct::gl::test
