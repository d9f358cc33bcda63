// The fixed-point reduction makes the GL frame reproducible: two runs give the same bytes in the
// voxels and in every image, whatever order llvmpipe's threads ran the fragments in.
#include <cstring>

#include "gl_test_util.h"

namespace vct::gl::test {

namespace {
template <class T>
bool same_bits(const T& a, const T& b) {
  return a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}
}  // namespace

TEST(GlDeterminism, FixedPointFrameIsReproducible) {
  VCT_REQUIRE_GL();
  Settings s = small_settings();
  s.vct.bounces = 2;
  const FrameResult a = render_gl_frame(*ctx, cornell_box(), s);
  const FrameResult b = render_gl_frame(*ctx, cornell_box(), s);
  EXPECT_TRUE(same_bits(a.voxels.radiance, b.voxels.radiance));
  EXPECT_TRUE(same_bits(a.voxels.fragments, b.voxels.fragments));
  for (size_t l = 0; l < a.mips.iso.size(); ++l) EXPECT_TRUE(same_bits(a.mips.iso[l], b.mips.iso[l])) << l;
  EXPECT_TRUE(same_bits(a.images.final_image, b.images.final_image));
  EXPECT_EQ(a.multibounce_energy, b.multibounce_energy);
}

}  // namespace vct::gl::test
