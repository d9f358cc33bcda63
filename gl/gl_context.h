// A headless OpenGL 4.5 core context made current on the calling thread, on the EGL display that
// --gl-device picks (gl_device.h): an EGL device (hardware first) or Mesa's surfaceless platform.
// No display server, window or pbuffer. Debug output (KHR_debug) goes to stderr; GL errors are
// fatal (a std::runtime_error naming where they were detected).
#pragma once

#include <string>

namespace vct::gl {

/// Throws vct::InputError when `device_spec` names an EGL device this machine does not have (an
/// index past the end, a name no device matches), as GlContext's constructor would, so a command
/// refuses it before its run directory exists. Opens a probe context only for a name that no
/// device's EGL strings contain (GL_RENDERER needs one).
void check_gl_device_exists(const std::string& device_spec);

class GlContext {
 public:
  /// Creates and makes current a 4.5 core context on the display `device_spec` names
  /// (parse_device_spec; "" = the first hardware EGL device, else Mesa surfaceless). Throws
  /// vct::InputError for a device that does not exist, vct::EnvironmentError when the machine
  /// (or the chosen device) cannot provide a 4.5 core context.
  explicit GlContext(const std::string& device_spec = "");
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  const std::string& vendor() const { return vendor_; }
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  /// Where the context lives, e.g. "egl device 0 (EGL_MESA_device_software)" or "mesa surfaceless".
  const std::string& device() const { return device_; }
  /// GL_MAX_FRAMEBUFFER_SAMPLES: the largest sample count an attachment-less FBO accepts.
  int max_framebuffer_samples() const { return max_samples_; }

 private:
  bool open(void* display, const std::string& description, std::string& why);
  void release();  // destroys the context (the display stays: EGL displays are per process)
  void* display_ = nullptr;
  void* context_ = nullptr;
  // The context current before this one (restored when this one goes): a device probe or a
  // second context never leaves another context's thread without its context.
  void* previous_display_ = nullptr;
  void* previous_context_ = nullptr;
  void* previous_draw_ = nullptr;
  void* previous_read_ = nullptr;
  std::string vendor_, renderer_, version_, device_;
  int max_samples_ = 1;
};

/// Throws std::runtime_error("GL error 0x.. after <where>") if glGetError reports anything.
void check_gl(const char* where);

/// Forgets debug-output errors already reported another way (shader compile / link logs).
void discard_debug_errors();

}  // namespace vct::gl
