// Which EGL display a GL context is made on: one of the machine's EGL devices
// (EGL_EXT_device_enumeration + EGL_EXT_device_query + EGL_EXT_platform_device: NVIDIA, AMD, Intel
// render nodes, and Mesa's own software device), or Mesa's surfaceless platform. Headless: no X,
// no window, no pbuffer. docs/gl_backend.md, "Devices".
#pragma once

#include <string>
#include <vector>

namespace vct::gl {

/// One EGL device as EGL_EXT_device_query describes it (before any context is made on it).
struct EglDevice {
  int index = 0;             // position in eglQueryDevicesEXT's list
  std::string extensions;    // the device's extension string
  std::string drm_file;      // EGL_DRM_DEVICE_FILE_EXT ("" when not reported)
  std::string render_node;   // EGL_DRM_RENDER_NODE_FILE_EXT ("" when not reported)
  bool software = false;     // EGL_MESA_device_software: Mesa's CPU rasterizer (llvmpipe)
  void* handle = nullptr;    // EGLDeviceEXT
};

/// Every EGL device of the machine; empty when EGL lacks device enumeration.
std::vector<EglDevice> list_egl_devices();

/// Mesa's surfaceless platform instead of a device (`--gl-device surfaceless`).
inline constexpr const char* kSurfacelessDevice = "surfaceless";

/// What `--gl-device SPEC` asks for: "" = automatic (the first hardware device, else Mesa
/// surfaceless), "N" = device N of list_egl_devices(), "surfaceless", or any other text = the
/// first device whose extension string, DRM file, render node or GL_RENDERER contains it
/// (case-insensitive; GL_RENDERER needs a context, so GlContext resolves names).
struct DeviceSpec {
  enum class Kind { Automatic, Index, Surfaceless, Name } kind = Kind::Automatic;
  int index = -1;
  std::string name;
};

/// Parses SPEC; throws InputError("--gl-device", ...) on a negative or malformed index.
DeviceSpec parse_device_spec(const std::string& spec);

/// Case-insensitive substring test used to match device names.
bool contains_ignoring_case(const std::string& haystack, const std::string& needle);

}  // namespace vct::gl
