// The headless context: EGL surfaceless, OpenGL 4.5 core, the extensions the pipeline relies on.
#include "gl_test_util.h"
#include "gl/gl_api.h"

namespace vct::gl::test {

TEST(GlContext, IsCore45WithImagesAndCompute) {
  VCT_REQUIRE_GL();
  EXPECT_FALSE(ctx->renderer().empty());
  EXPECT_EQ(ctx->version().rfind("4.5", 0) == 0 || ctx->version().rfind("4.6", 0) == 0, true) << ctx->version();
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  GLint image_units = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &image_units);
  EXPECT_GE(image_units, 8);  // voxel resolve binds 8 images
  EXPECT_GE(ctx->max_framebuffer_samples(), 4);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_SAMPLES, &max_samples);
  EXPECT_EQ(max_samples, ctx->max_framebuffer_samples());
  EXPECT_NO_THROW(check_gl("test"));
}

TEST(GlContext, GlErrorsAreReportedWithTheirPlace) {
  VCT_REQUIRE_GL();
  glEnable(GLenum(0x7fff));  // GL_INVALID_ENUM
  try {
    check_gl("a deliberate bad enum");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a deliberate bad enum"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0x0500"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_gl("after the error was taken"));
}

}  // namespace vct::gl::test
