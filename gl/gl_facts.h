// The driver's facts the CPU reference must mirror (or the comparison must know), read at run
// time on the current context: GL_VENDOR / GL_RENDERER / GL_VERSION, GL_MAX_FRAMEBUFFER_SAMPLES,
// GL_SUBPIXEL_BITS, the MSAA sample positions of the voxelization sample count
// (glGetMultisamplefv(GL_SAMPLE_POSITION), GL 4.5 §14.3.1) and the conservative-raster
// extensions. What the driver does not report is listed in BackendFacts::unreported.
#pragma once

#include <string>
#include <vector>

#include "stages/backend_facts.h"

namespace vct::gl {

class GlContext;

/// Facts of `context` (current) for a voxelization pass asking for `requested_samples`: the
/// sample count is clamped to GL_MAX_FRAMEBUFFER_SAMPLES, and the positions are those of a
/// multisample framebuffer of that count. One sample = the pixel centre (GL 4.5 §14.6.1).
BackendFacts read_driver_facts(const GlContext& context, int requested_samples);

/// The context's GL extensions (glGetStringi(GL_EXTENSIONS, i)).
std::vector<std::string> gl_extensions();

}  // namespace vct::gl
