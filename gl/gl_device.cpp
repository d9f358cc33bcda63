#include "gl_device.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace vct::gl {
namespace {

std::string device_string(PFNEGLQUERYDEVICESTRINGEXTPROC query, EGLDeviceEXT device, EGLint name) {
  const char* s = query(device, name);
  // A device without the extension that defines `name` answers NULL with EGL_BAD_PARAMETER;
  // the error is cleared so it does not leak into a later eglGetError.
  if (!s) eglGetError();
  return s ? s : "";
}

bool has_word(const std::string& list, const std::string& word) {
  return (" " + list + " ").find(" " + word + " ") != std::string::npos;
}

}  // namespace

std::vector<EglDevice> list_egl_devices() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client || !has_word(client, "EGL_EXT_device_enumeration") || !has_word(client, "EGL_EXT_device_query"))
    return {};
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (!query_devices || !query_string) return {};
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count), nullptr);
  if (!query_devices(count, handles.data(), &count)) return {};
  std::vector<EglDevice> out;
  for (EGLint i = 0; i < count; ++i) {
    EglDevice d;
    d.index = int(i);
    d.handle = handles[size_t(i)];
    d.extensions = device_string(query_string, handles[size_t(i)], EGL_EXTENSIONS);
    if (has_word(d.extensions, "EGL_EXT_device_drm"))
      d.drm_file = device_string(query_string, handles[size_t(i)], EGL_DRM_DEVICE_FILE_EXT);
    if (has_word(d.extensions, "EGL_EXT_device_drm_render_node"))
      d.render_node = device_string(query_string, handles[size_t(i)], EGL_DRM_RENDER_NODE_FILE_EXT);
    d.software = has_word(d.extensions, "EGL_MESA_device_software");
    out.push_back(d);
  }
  return out;
}

DeviceSpec parse_device_spec(const std::string& spec) {
  DeviceSpec d;
  if (spec.empty() || spec == "auto") return d;
  if (spec == kSurfacelessDevice) {
    d.kind = DeviceSpec::Kind::Surfaceless;
    return d;
  }
  const bool digits = std::all_of(spec.begin(), spec.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (digits) {
    if (spec.size() > 4) throw InputError("--gl-device", "device index '" + spec + "' is out of range");
    d.kind = DeviceSpec::Kind::Index;
    d.index = std::stoi(spec);
    return d;
  }
  if (spec[0] == '-' && spec.size() > 1 && std::isdigit(static_cast<unsigned char>(spec[1])))
    throw InputError("--gl-device", "device index must be 0 or more, got '" + spec + "'");
  d.kind = DeviceSpec::Kind::Name;
  d.name = spec;
  return d;
}

bool contains_ignoring_case(const std::string& haystack, const std::string& needle) {
  auto lower = [](std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  return lower(haystack).find(lower(needle)) != std::string::npos;
}

}  // namespace vct::gl
