// A frame rendered while RenderDoc is injected (`renderdoccmd capture vct render --backend gl`)
// becomes one capture. Our context is surfaceless and never swaps, so RenderDoc's frame delimiter
// (a present) never comes: the frame is bracketed with its in-app API (renderdoc_app.h,
// Debian's librenderdoc-dev). Without RenderDoc loaded, or built without the header, nothing
// happens (docs/external_format.md, "From a RenderDoc capture").
#pragma once

namespace vct::gl {

class RenderDocFrame {
 public:
  /// Starts a capture on the current EGL context when RenderDoc is loaded in this process.
  RenderDocFrame();
  /// Checks the frame's own GL errors (check_gl), then ends the capture (RenderDoc writes the
  /// file) and forgets the errors RenderDoc's end leaves on a surfaceless context: its thumbnail
  /// read of the default framebuffer, which such a context lacks, sets
  /// GL_INVALID_FRAMEBUFFER_OPERATION (GL 4.5 §9.4.4).
  void end();
  /// Ends a capture end() did not (the frame threw).
  ~RenderDocFrame();
  RenderDocFrame(const RenderDocFrame&) = delete;
  RenderDocFrame& operator=(const RenderDocFrame&) = delete;

 private:
  void* api_ = nullptr;      // RENDERDOC_API_1_1_2*, when loaded
  void* context_ = nullptr;  // the EGLContext the capture is on
};

}  // namespace vct::gl
