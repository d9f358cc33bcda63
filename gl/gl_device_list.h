// `vct info --gl`: every EGL device of the machine and Mesa surfaceless, each opened in turn to
// say what it offers (GL 4.5 core or why not, renderer, MSAA, sample positions, sub-pixel bits,
// conservative rasterization), and which one `--gl-device` picks by default.
#pragma once

#include <nlohmann/json.hpp>

namespace vct::gl {

/// {"devices": [{"spec": "0", "kind": "software"|"hardware"|"surfaceless", "egl": {...},
///  "status": "ok"|"unavailable: ...", "facts": BackendFacts at the max sample count}, ...],
///  "default": the description of the device an automatic --gl-device opens ("" = none)}.
nlohmann::json list_gl_devices();

}  // namespace vct::gl
