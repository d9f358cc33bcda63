// The GL 4.5 VCT frame: every stage as a GPU pass, every result read back into the reference's
// stage types (ref/stages/stage_types.h), GPU timer-query times in FrameResult::timings_ms and the
// driver's facts in FrameResult::facts (gl_facts.h). Throws vct::EnvironmentError without a
// context, std::runtime_error on shader or GL errors (naming the shader / the call site).
#pragma once

#include <functional>
#include <string>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::gl {

class GlContext;
struct GlFrame;

/// How the GL frame runs, apart from the VCT settings both backends share.
struct GlOptions {
  std::string device;  // --gl-device (gl_device.h: "" = first hardware device, else surfaceless)
  std::string fault;   // "" or a deliberate fault of gl_faults.h
  // Whether the frame brackets its own RenderDoc capture (gl_renderdoc.h); false for a program
  // that renders its own passes after it in one capture (tests/capture/test_engine.cpp).
  bool renderdoc_capture = true;
  // Passes of a program that embeds the frame, run after ours on the frame's textures (gl_frame.h)
  // inside the same capture: tests/capture/test_engine.cpp's own direct light and display.
  std::function<void(GlFrame&)> extra_passes;
};

/// What the GL frame refuses, found without a context (vct::InputError): more lights than the
/// shaders take, settings only the reference runs, an unknown fault, a malformed --gl-device.
/// Commands call it before they create their run directory (a refused frame leaves none behind);
/// render_gl_frame calls it again.
void check_gl_accepts(const Scene& scene, const Settings& settings, const GlOptions& options = {});

/// Creates a context on options.device for this frame (and destroys it afterwards).
FrameResult render_gl_frame(const Scene& scene, const Settings& settings, const GlOptions& options = {});

/// Same, on a context the caller keeps current (tests and benchmarks render several frames);
/// options.device is not used.
FrameResult render_gl_frame(GlContext& context, const Scene& scene, const Settings& settings,
                            const GlOptions& options = {});

}  // namespace vct::gl
