// The image takes the camera's aspect ratio (docs/scenes.md, "Camera"): a glTF perspective camera's
// aspectRatio decides the width from the height (or the height from --width alone); forcing both
// --width and --height keeps them and warns that the framing changes.
#pragma once

#include <string>

#include "core/settings.h"
#include "options.h"
#include "scene/scene.h"

namespace vct::app {

/// The image size for `scene`'s camera: unchanged without aspectRatio; with it, width =
/// round(height x aspect) (height = round(width / aspect) when only --width was given), at least 1,
/// for the VCT and the path-tracer images alike. `warning` gets a sentence when --width and --height
/// both force a different aspect, empty otherwise.
Settings fit_image_to_camera(Settings s, const Scene& scene, const CommonOptions& o, std::string& warning);

/// fit_image_to_camera, printing its warning as "vct: warning: FILE: ..." and keeping it in
/// scene.stats.warnings (so run.json and the report carry it).
Settings fit_image_to_camera_and_warn(const Settings& s, Scene& scene, const CommonOptions& o);

}  // namespace vct::app
