#include "gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "gl_api.h"

namespace vct::gl {
namespace {

std::string hex(unsigned v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", v);
  return buf;
}

// KHR_debug: errors are printed and remembered; check_gl() turns them into exceptions, because
// throwing through the driver's callback frame is not allowed.
std::string g_debug_error;

void APIENTRY debug_callback(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei /*length*/,
                               const GLchar* message, const void* /*user*/) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  std::fprintf(stderr, "[gl] %s (id %u, type %s)\n", message, id, hex(type).c_str());
  if (type == GL_DEBUG_TYPE_ERROR && g_debug_error.empty()) g_debug_error = message;
}

bool has_extension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

}  // namespace

GlContext::GlContext() {
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) throw EnvironmentError("GL backend: EGL has no eglGetPlatformDisplayEXT");
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
    throw EnvironmentError("GL backend: no EGL surfaceless display (Mesa's EGL_MESA_platform_surfaceless)");
  display_ = display;
  const char* exts = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(exts, "EGL_KHR_no_config_context") && !has_extension(exts, "EGL_MESA_configless_context")) {
    eglTerminate(display);
    throw EnvironmentError("GL backend: EGL lacks EGL_KHR_no_config_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(display);
    throw EnvironmentError("GL backend: EGL cannot bind the OpenGL API");
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    throw EnvironmentError("GL backend: no OpenGL 4.5 core context (EGL error " + hex(unsigned(eglGetError())) + ")");
  }
  context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    eglTerminate(display);
    throw EnvironmentError("GL backend: eglMakeCurrent without a surface failed");
  }
  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debug_callback, nullptr);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_SAMPLES, &max_samples_);
  g_debug_error.clear();
  check_gl("context creation");
}

GlContext::~GlContext() {
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  // The display is not terminated: EGL displays are per-process singletons and other contexts
  // (another test, the benchmark's next iteration) may still use it.
}

void discard_debug_errors() { g_debug_error.clear(); }

void check_gl(const char* where) {
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR || !g_debug_error.empty()) {
    std::string msg = "GL error " + hex(err) + " after " + where;
    if (!g_debug_error.empty()) msg += ": " + g_debug_error;
    g_debug_error.clear();
    throw std::runtime_error(msg);
  }
}

}  // namespace vct::gl
