// Occlusion culling by a depth pre-pass (GL_LESS depth only, then GL_LEQUAL shading) must not
// change a single bit of any image: `invariant gl_Position` gives both passes the same depths.
#include <cstring>

#include "gl_test_util.h"

namespace vct::gl::test {

namespace {
bool same_bits(const Image& a, const Image& b) {
  return a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}
}  // namespace

TEST(GlDepthPrepass, ImageIsBitIdentical) {
  VCT_REQUIRE_GL();
  Settings with = small_settings(32, 96);
  with.vct.depth_prepass = true;
  Settings without = with;
  without.vct.depth_prepass = false;
  const FrameResult a = render_gl_frame(*ctx, cornell_box(), with);
  const FrameResult b = render_gl_frame(*ctx, cornell_box(), without);
  EXPECT_TRUE(a.timings_ms.count("depth_prepass"));
  EXPECT_FALSE(b.timings_ms.count("depth_prepass"));
  EXPECT_TRUE(same_bits(a.gbuffer.depth, b.gbuffer.depth));
  EXPECT_TRUE(same_bits(a.gbuffer.position, b.gbuffer.position));
  EXPECT_TRUE(same_bits(a.gbuffer.normal, b.gbuffer.normal));
  EXPECT_TRUE(same_bits(a.images.direct, b.images.direct));
  EXPECT_TRUE(same_bits(a.images.final_image, b.images.final_image));
  // Not vacuous: the frame has lit, covered pixels.
  double sum = 0.0;
  for (float v : a.images.final_image.data) sum += double(v);
  EXPECT_GT(sum, 1.0);
}

}  // namespace vct::gl::test

namespace vct::gl::test {

TEST(GlDepthPrepass, AlphaMaskedFoliageIsBitIdentical) {
  // The pre-pass discards the masked fragments the G-buffer pass discards (depth_only.frag and
  // gbuffer.frag share alpha_mask.glsl): with GL_LEQUAL, a pre-pass that kept them would leave
  // holes in the leaves' gaps, where the panel and the floor must show.
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/foliage.gltf");
  Settings with = small_settings(32, 96);
  with.vct.depth_prepass = true;
  Settings without = with;
  without.vct.depth_prepass = false;
  const FrameResult a = render_gl_frame(*ctx, scene, with);
  const FrameResult b = render_gl_frame(*ctx, scene, without);
  EXPECT_TRUE(same_bits(a.gbuffer.depth, b.gbuffer.depth));
  EXPECT_TRUE(same_bits(a.gbuffer.position, b.gbuffer.position));
  EXPECT_TRUE(same_bits(a.gbuffer.albedo, b.gbuffer.albedo));
  EXPECT_TRUE(same_bits(a.images.final_image, b.images.final_image));
}

}  // namespace vct::gl::test
