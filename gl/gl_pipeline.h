// The GL 4.5 VCT frame: every stage as a GPU pass, every result read back into the reference's
// stage types (ref/stages/stage_types.h), GPU timer-query times in FrameResult::timings_ms and
// GL_RENDERER / GL_VERSION in FrameResult::info. Throws vct::EnvironmentError without a context,
// std::runtime_error on shader or GL errors (naming the shader / the call site).
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::gl {

class GlContext;

/// Creates a context for this frame (and destroys it afterwards).
FrameResult render_gl_frame(const Scene& scene, const Settings& settings);

/// Same, on a context the caller keeps current (tests and benchmarks render several frames).
FrameResult render_gl_frame(GlContext& context, const Scene& scene, const Settings& settings);

}  // namespace vct::gl
