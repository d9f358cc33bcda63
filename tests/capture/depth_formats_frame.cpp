// A one-frame GL program whose only work is two packed depth-stencil textures with known contents,
// for `vct import-capture`'s depth decoding (tests/cli/import_capture_depth_test.cpp): RenderDoc
// captures it (in-app API, gl/gl_renderdoc.h), the importer reads each texture after its debug
// group. Texel (x, y) of each 4x2 texture (y up) holds depth (x + 4 y + 1) / 10 (none a multiple of 1 / (2^24 - 1)) and stencil 0xA5,
// written by one scissored clear per texel (glClearNamedFramebufferfi, GL 4.5 section 17.4.3.1:
// the depth converted to the format as a fragment's would be, section 2.3.5.2 for the UNORM one).
// Exit 0 written, 3 no GL 4.5 context.
#include <cstdio>
#include <exception>

#include "core/error.h"
#include "gl/gl_api.h"
#include "gl/gl_context.h"
#include "gl/gl_renderdoc.h"

namespace {

constexpr int kWidth = 4, kHeight = 2;
constexpr GLint kStencil = 0xA5;

// Creates `format` (a depth-stencil format), labels it `name` and clears each texel inside the
// debug group `name`, so the map's event "<name>" is after its last clear.
void write_depth_texture(GLenum format, const char* name) {
  GLuint texture = 0, fbo = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, kWidth, kHeight);
  glObjectLabel(GL_TEXTURE, texture, -1, name);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_DEPTH_STENCIL_ATTACHMENT, texture, 0);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 1, -1, name);
  glEnable(GL_SCISSOR_TEST);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      glScissor(x, y, 1, 1);
      glClearNamedFramebufferfi(fbo, GL_DEPTH_STENCIL, 0, float(x + kWidth * y + 1) / 10.0f, kStencil);
    }
  glDisable(GL_SCISSOR_TEST);
  glPopDebugGroup();
  glFinish();
}

}  // namespace

int main() {
  try {
    vct::gl::GlContext context;
    vct::gl::RenderDocFrame frame;
    write_depth_texture(GL_DEPTH24_STENCIL8, "depth24_stencil8");
    write_depth_texture(GL_DEPTH32F_STENCIL8, "depth32f_stencil8");
    frame.end();
    vct::gl::check_gl("the depth-format frame");
  } catch (const vct::EnvironmentError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
