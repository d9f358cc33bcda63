// Smoke: the whole GL frame runs on the Cornell box and every stage is read back.
#include "gl_test_util.h"
#include "io/image_io.h"

namespace vct::gl::test {

TEST(GlFrame, RendersEveryStage) {
  VCT_REQUIRE_GL();
  const FrameResult r = render_gl_frame(*ctx, cornell_box(), small_settings());
  EXPECT_EQ(r.backend, "gl");
  EXPECT_NE(r.info.at("GL_RENDERER").find(""), std::string::npos);
  ASSERT_FALSE(r.shadow_maps.empty());
  EXPECT_EQ(r.gbuffer.position.width, 64);
  EXPECT_EQ(r.voxels.radiance.nx, 32);
  EXPECT_EQ(r.mips.iso.size(), 6u);
  if (const char* dir = std::getenv("VCT_GL_SMOKE_DIR")) {
    write_png(std::string(dir) + "/final.png", r.images.final_image);
    write_png(std::string(dir) + "/direct.png", r.images.direct);
    write_png(std::string(dir) + "/diffuse.png", r.images.indirect_diffuse);
    write_png_linear(std::string(dir) + "/shadow.png", r.shadow_maps[0].depth, 0.9f, 1.0f);
  }
  for (const auto& [k, v] : r.timings_ms) std::printf("%s %.2f ms\n", k.c_str(), v);
}

}  // namespace vct::gl::test
