#include "gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl_api.h"
#include "gl_device.h"

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

// Makes a 4.5 core context current on an initialized display. Configless when the display allows
// it (EGL_KHR_no_config_context); otherwise with any OpenGL-renderable config, made current
// without a surface (EGL_KHR_surfaceless_context), as NVIDIA's EGL device platform wants.
void* make_context(EGLDisplay display, std::string& why) {
  const char* exts = eglQueryString(display, EGL_EXTENSIONS);
  const bool configless = has_extension(exts, "EGL_KHR_no_config_context") || has_extension(exts, "EGL_MESA_configless_context");
  if (!configless && !has_extension(exts, "EGL_KHR_surfaceless_context")) {
    why = "EGL lacks EGL_KHR_no_config_context and EGL_KHR_surfaceless_context";
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "EGL cannot bind the OpenGL API";
    return nullptr;
  }
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!configless) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(display, want, &config, 1, &n) || n < 1) {
      why = "no OpenGL-renderable EGL config";
      return nullptr;
    }
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    why = "no OpenGL 4.5 core context (EGL error " + hex(unsigned(eglGetError())) + ")";
    return nullptr;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    why = "eglMakeCurrent without a surface failed";
    return nullptr;
  }
  return context;
}

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

EGLDisplay surfaceless_display() {
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!get_platform_display || !has_extension(client, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  return get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

EGLDisplay device_display(const EglDevice& d) {
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!get_platform_display || !has_extension(client, "EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
  return get_platform_display(EGL_PLATFORM_DEVICE_EXT, static_cast<EGLDeviceEXT>(d.handle), nullptr);
}

std::string describe(const EglDevice& d) {
  std::string s = "egl device " + std::to_string(d.index) + " (" + (d.extensions.empty() ? "no extensions" : d.extensions);
  if (!d.drm_file.empty()) s += ", " + d.drm_file;
  if (!d.render_node.empty() && d.render_node != d.drm_file) s += ", " + d.render_node;
  return s + ")";
}

bool device_matches(const EglDevice& d, const std::string& name) {
  return contains_ignoring_case(d.extensions, name) || contains_ignoring_case(d.drm_file, name) ||
         contains_ignoring_case(d.render_node, name);
}

InputError no_device_with_index(int index, size_t count) {
  return InputError("--gl-device", "no EGL device " + std::to_string(index) + " (this machine has " +
                                       std::to_string(count) + "; `vct info --gl` lists them)");
}

}  // namespace

bool GlContext::open(void* display_handle, const std::string& description, std::string& why) {
  auto display = static_cast<EGLDisplay>(display_handle);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    why = description + ": EGL display does not initialize";
    return false;
  }
  void* context = make_context(display, why);
  if (!context) {
    why = description + ": " + why;
    return false;
  }
  display_ = display;
  context_ = context;
  device_ = description;
  vendor_ = gl_string(GL_VENDOR);
  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debug_callback, nullptr);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_SAMPLES, &max_samples_);
  g_debug_error.clear();
  check_gl("context creation");
  return true;
}

GlContext::GlContext(const std::string& device_spec) {
  previous_display_ = eglGetCurrentDisplay();
  previous_context_ = eglGetCurrentContext();
  previous_draw_ = eglGetCurrentSurface(EGL_DRAW);
  previous_read_ = eglGetCurrentSurface(EGL_READ);
  const DeviceSpec spec = parse_device_spec(device_spec);
  const std::vector<EglDevice> devices = spec.kind == DeviceSpec::Kind::Surfaceless ? std::vector<EglDevice>{} : list_egl_devices();
  std::string why, tried;
  auto note = [&] { tried += (tried.empty() ? "" : "; ") + why; };
  switch (spec.kind) {
    case DeviceSpec::Kind::Index:
      if (spec.index >= int(devices.size())) throw no_device_with_index(spec.index, devices.size());
      if (open(device_display(devices[size_t(spec.index)]), describe(devices[size_t(spec.index)]), why)) return;
      throw EnvironmentError("GL backend: " + why);
    case DeviceSpec::Kind::Surfaceless:
      if (open(surfaceless_display(), "mesa surfaceless", why)) return;
      throw EnvironmentError("GL backend: " + why + " (Mesa's EGL_MESA_platform_surfaceless)");
    case DeviceSpec::Kind::Name: {
      // The name may be in the device's EGL strings or only in GL_RENDERER / GL_VENDOR, which
      // need a context: each device is opened in turn and kept when it matches.
      for (const EglDevice& d : devices) {
        if (!open(device_display(d), describe(d), why)) {
          // Named by its EGL strings but unusable: say why, rather than "no such device".
          if (device_matches(d, spec.name)) throw EnvironmentError("GL backend: " + why);
          note();
          continue;
        }
        if (device_matches(d, spec.name) || contains_ignoring_case(renderer_, spec.name) ||
            contains_ignoring_case(vendor_, spec.name))
          return;
        release();
      }
      throw InputError("--gl-device", "no EGL device matches '" + spec.name + "' (`vct info --gl` lists them)");
    }
    case DeviceSpec::Kind::Automatic:
      // The first hardware device; then Mesa surfaceless; then any software device.
      for (const EglDevice& d : devices)
        if (!d.software) {
          if (open(device_display(d), describe(d), why)) return;
          note();
        }
      if (open(surfaceless_display(), "mesa surfaceless", why)) return;
      note();
      for (const EglDevice& d : devices)
        if (d.software) {
          if (open(device_display(d), describe(d), why)) return;
          note();
        }
      throw EnvironmentError("GL backend: no OpenGL 4.5 core context on any EGL device or Mesa surfaceless (" +
                             (tried.empty() ? std::string("no EGL devices, no surfaceless platform") : tried) + ")");
  }
}

void check_gl_device_exists(const std::string& device_spec) {
  const DeviceSpec spec = parse_device_spec(device_spec);
  if (spec.kind == DeviceSpec::Kind::Index) {
    const size_t count = list_egl_devices().size();
    if (spec.index >= int(count)) throw no_device_with_index(spec.index, count);
  } else if (spec.kind == DeviceSpec::Kind::Name) {
    for (const EglDevice& d : list_egl_devices())
      if (device_matches(d, spec.name)) return;
    // The name may be in GL_RENDERER / GL_VENDOR only, which need a context: the constructor
    // resolves it and throws InputError when no device matches. A device that exists but cannot
    // give a context is the GL frame's own failure (reported by the run), not bad input.
    try {
      GlContext probe(device_spec);
    } catch (const EnvironmentError&) {
    }
  }
}

void GlContext::release() {
  if (!context_) return;
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  context_ = nullptr;
  if (previous_context_ != EGL_NO_CONTEXT)
    eglMakeCurrent(static_cast<EGLDisplay>(previous_display_), static_cast<EGLSurface>(previous_draw_),
                   static_cast<EGLSurface>(previous_read_), static_cast<EGLContext>(previous_context_));
  // The display is not terminated: EGL displays are per-process singletons and other contexts
  // (another test, the benchmark's next iteration) may still use it.
}

GlContext::~GlContext() { release(); }

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
