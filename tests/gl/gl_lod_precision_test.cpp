// GL's own lambda against the LOD precision (scene/texture_lod.h kLodPrecision = 2^-4, dEQP's
// accepted lodBits 4; docs/compare.md "Texture LOD"). On the level-marked wall
// (tests/ref/level_marked_wall.h) the camera's roughness is a blend of two constant mip levels,
// so GL's lambda reads back exactly. At lambda 2.264, where a linear-mantissa log2 is worst,
// llvmpipe's lambda (0.5 fast_log2(rho^2)) is 0.043 low: inside 2^-4, outside dEQP's lodBits 6
// (2^-6) that the reference used before. A GL computing log2 exactly reads back 2.264.
#include <algorithm>
#include <cstdio>

#include "gl_test_util.h"
#include "level_marked_wall.h"
#include "scene/texture_lod.h"

namespace vct::gl::test {
namespace {

TEST(GlLodPrecision, TheCameraLambdaIsWithinTheLodPrecision) {
  VCT_REQUIRE_GL();
  const Scene scene = vct::test::level_marked_wall();
  const Settings s = small_settings(16, vct::test::kLevelWallPixels);
  const FrameResult gl = render_gl_frame(*ctx, scene, s);
  const double exact = vct::test::level_wall_lambda();
  const int k = int(std::floor(exact));
  double lo = 1e9, hi = -1e9;
  for (int y = 0; y < s.vct.height; ++y)
    for (int x = 0; x < s.vct.width; ++x) {
      ASSERT_GT(gl.gbuffer.coverage.at(x, y, 0), 0.0f);
      const double l = vct::test::level_wall_lambda_of(double(gl.gbuffer.material.at(x, y, 1)), k);
      lo = std::min(lo, l);
      hi = std::max(hi, l);
    }
  std::printf("  camera lambda %.4f (a linear-mantissa log2: %.4f): GL's %.4f..%.4f\n", exact,
              vct::test::fast_log2_lambda(std::exp2(exact)), lo, hi);
  // The 8-bit blend weight (filter-weights row) moves the read-back by up to 2^-8 more.
  const double weight = 1.0 / 256.0;
  EXPECT_GE(lo, exact - kLodPrecision - weight);
  EXPECT_LE(hi, exact + kLodPrecision + weight);
}

}  // namespace
}  // namespace vct::gl::test
