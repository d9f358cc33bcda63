// A headless OpenGL 4.5 core context: EGL on Mesa's surfaceless platform (no display, no window),
// made current on the calling thread. Debug output (KHR_debug) goes to stderr; GL errors are
// fatal (a std::runtime_error naming where they were detected).
#pragma once

#include <string>

namespace vct::gl {

class GlContext {
 public:
  /// Creates and makes current a 4.5 core context; throws vct::EnvironmentError when the machine
  /// cannot provide one (no EGL, no surfaceless platform, no 4.5 core).
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  /// GL_MAX_FRAMEBUFFER_SAMPLES: the largest sample count an attachment-less FBO accepts.
  int max_framebuffer_samples() const { return max_samples_; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string renderer_, version_;
  int max_samples_ = 1;
};

/// Throws std::runtime_error("GL error 0x.. after <where>") if glGetError reports anything.
void check_gl(const char* where);

/// Forgets debug-output errors already reported another way (shader compile / link logs).
void discard_debug_errors();

}  // namespace vct::gl
