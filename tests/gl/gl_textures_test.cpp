// Textured materials and normal mapping in the G-buffer: GL's samplers (SRGB8_ALPHA8 decoded
// before filtering, LINEAR without mipmaps, the glTF wrap modes) against ref/scene/surface.cpp's
// sample_texture, on the demo room (brick base colour and normal maps).
#include "gl_test_util.h"
#include "stages/gbuffer.h"

namespace vct::gl::test {

TEST(GlTextures, TexturedGBufferMatchesTheCpu) {
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/demo_room.gltf");
  ASSERT_FALSE(scene.textures.empty());
  const Settings s = small_settings(32, 96);
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const GBuffer r = render_gbuffer(scene, s.vct);
  size_t both = 0, coverage_mismatch = 0;
  double albedo_sum = 0.0, albedo_max = 0.0, normal_sum = 0.0, albedo_ref = 0.0;
  size_t albedo_over = 0;
  for (int y = 0; y < r.coverage.height; ++y)
    for (int x = 0; x < r.coverage.width; ++x) {
      const bool cg = g.gbuffer.coverage.at(x, y, 0) > 0.0f, cr = r.coverage.at(x, y, 0) > 0.0f;
      coverage_mismatch += cg != cr;
      if (!cg || !cr) continue;
      ++both;
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(g.gbuffer.albedo.at(x, y, c)) - double(r.albedo.at(x, y, c)));
        albedo_sum += d;
        albedo_ref += double(r.albedo.at(x, y, c));
        albedo_max = std::max(albedo_max, d);
        albedo_over += d > 4.0 / 255.0;
        normal_sum += std::abs(double(g.gbuffer.normal.at(x, y, c)) - double(r.normal.at(x, y, c)));
      }
    }
  std::printf("[gl vs ref] textured gbuffer: %zu pixels, coverage mismatches %zu, albedo mean %.3g max %.3g "
              "(> 4/255: %zu), normal mean %.3g\n",
              both, coverage_mismatch, albedo_sum / double(3 * both), albedo_max, albedo_over,
              normal_sum / double(3 * both));
  EXPECT_LE(coverage_mismatch, both / 200);  // silhouette ties of the statue only
  // Bilinear weights: llvmpipe filters sRGB-decoded texels with 8-bit fractional weights, the CPU
  // in float, so a texel step of contrast c differs by up to c/256; texture coordinates also differ
  // by interpolation rounding. Bound the mean tightly and the worst case loosely.
  EXPECT_LE(albedo_sum / albedo_ref, 5e-3);
  EXPECT_LE(albedo_over, both / 50);
  EXPECT_LE(normal_sum / double(3 * both), 5e-3);
}

}  // namespace vct::gl::test
