#include "gl_facts.h"

#include <algorithm>

#include "gl_api.h"
#include "gl_context.h"

namespace vct::gl {
namespace {

// Positions of a framebuffer with `samples` samples. An attachment-less framebuffer would be the
// voxelization pass's own, but Mesa 22.3 answers GL_SAMPLES = 0 there, so the query uses an RGBA8
// multisample renderbuffer of the same count (the sample pattern is a property of the count).
std::vector<vec2> query_sample_positions(int samples, int& effective) {
  GLuint fbo = 0, rb = 0;
  glCreateFramebuffers(1, &fbo);
  glCreateRenderbuffers(1, &rb);
  glNamedRenderbufferStorageMultisample(rb, samples, GL_RGBA8, 4, 4);
  glNamedFramebufferRenderbuffer(fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  std::vector<vec2> positions;
  GLint n = 0;
  if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) glGetIntegerv(GL_SAMPLES, &n);
  effective = int(n);
  for (GLint i = 0; i < n; ++i) {
    GLfloat p[2] = {-1.0f, -1.0f};
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), p);
    positions.emplace_back(p[0], p[1]);
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &rb);
  while (glGetError() != GL_NO_ERROR) {
  }
  return positions;
}

bool inside_pixel(const std::vector<vec2>& p) {
  return std::all_of(p.begin(), p.end(), [](const vec2& v) { return v.x >= 0.0f && v.x < 1.0f && v.y >= 0.0f && v.y < 1.0f; });
}

}  // namespace

std::vector<std::string> gl_extensions() {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  std::vector<std::string> out;
  for (GLint i = 0; i < n; ++i) out.emplace_back(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))));
  return out;
}

BackendFacts read_driver_facts(const GlContext& context, int requested_samples) {
  BackendFacts f;
  f.device = context.device();
  f.vendor = context.vendor();
  f.renderer = context.renderer();
  f.version = context.version();
  f.max_samples = context.max_framebuffer_samples();
  f.msaa_samples_requested = requested_samples;
  GLint bits = -1;
  glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
  f.subpixel_bits = bits > 0 ? int(bits) : -1;
  if (f.subpixel_bits < 0) f.unreported.push_back("GL_SUBPIXEL_BITS: the driver answered no value");
  const int asked = std::min(std::max(requested_samples, 1), std::max(f.max_samples, 1));
  f.msaa_samples = asked;
  if (asked == 1) {
    f.sample_positions = {vec2(0.5f, 0.5f)};  // single-sampled rasterization tests the centre
  } else {
    int effective = 0;
    std::vector<vec2> p = query_sample_positions(asked, effective);
    if (effective >= asked && inside_pixel(p) && !p.empty()) {
      f.msaa_samples = effective;  // GL may give more samples than asked (GL 4.5 §9.2.4)
      f.sample_positions = std::move(p);
    } else {
      f.unreported.push_back("GL_SAMPLE_POSITION for " + std::to_string(asked) +
                             " samples: no multisample framebuffer of that count, or positions outside the pixel; "
                             "the CPU assumes the standard pattern");
    }
  }
  f.unreported.push_back(
      "texture filtering sub-texel precision: GL has no query (GL 4.5 §8.14.2 only says it is implementation-"
      "dependent); the texture bounds assume 8 bits (docs/compare.md)");
  for (const std::string& e : gl_extensions())
    if (e == "GL_NV_conservative_raster" || e == "GL_INTEL_conservative_rasterization" || e == "GL_NV_conservative_raster_dilate")
      f.conservative_raster.push_back(e);
  check_gl("driver facts");
  return f;
}

}  // namespace vct::gl
