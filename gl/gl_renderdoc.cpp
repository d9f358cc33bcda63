#include "gl_renderdoc.h"

#include <EGL/egl.h>
#include <dlfcn.h>

#include "gl_api.h"
#include "gl_context.h"

#if __has_include(<renderdoc_app.h>)
#include <renderdoc_app.h>
#define VCT_HAVE_RENDERDOC_APP 1
#endif

namespace vct::gl {

#ifdef VCT_HAVE_RENDERDOC_APP
namespace {
RENDERDOC_API_1_1_2* loaded_api() {
  // RTLD_NOLOAD: only a RenderDoc that injected itself into this process, never one loaded here.
  void* module = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
  if (!module) return nullptr;
  auto get_api = reinterpret_cast<pRENDERDOC_GetAPI>(dlsym(module, "RENDERDOC_GetAPI"));
  RENDERDOC_API_1_1_2* api = nullptr;
  if (!get_api || get_api(eRENDERDOC_API_Version_1_1_2, reinterpret_cast<void**>(&api)) != 1) return nullptr;
  return api;
}
}  // namespace

RenderDocFrame::RenderDocFrame() {
  RENDERDOC_API_1_1_2* api = loaded_api();
  if (!api) return;
  // The device must be the EGLContext: with NULL (any device) RenderDoc 1.24 finds no capturer for
  // a context that never presented, and EndFrameCapture returns 0 with no capture written.
  context_ = eglGetCurrentContext();
  api->StartFrameCapture(context_, nullptr);
  api_ = api;
}

void RenderDocFrame::end() {
  if (!api_) return;
  check_gl("the frame (before its RenderDoc capture ends)");
  static_cast<RENDERDOC_API_1_1_2*>(api_)->EndFrameCapture(context_, nullptr);
  api_ = nullptr;
  while (glGetError() != GL_NO_ERROR) {
  }
  discard_debug_errors();
}

RenderDocFrame::~RenderDocFrame() {
  if (api_) static_cast<RENDERDOC_API_1_1_2*>(api_)->EndFrameCapture(context_, nullptr);
}
#else
RenderDocFrame::RenderDocFrame() = default;
void RenderDocFrame::end() {}
RenderDocFrame::~RenderDocFrame() = default;
#endif

}  // namespace vct::gl
