// What the loader could not render as the file asks (skipped primitives, ignored skins or
// extensions, a scene without light): every command that renders says it on stderr and keeps it
// in run.json ("scene"/"warnings"), and the report shows it on its first screen (docs/scenes.md).
#pragma once

#include <string>

#include "core/settings.h"
#include "scene/gltf_loader.h"

namespace vct::app {

/// load_scene, then one stderr line per load warning: "vct: warning: FILE: what".
Scene load_scene_and_warn(const std::string& path_or_empty, const SceneLoadOptions& options);

/// The same, then the exposure setting applied to its sources (scene/exposure.h): the scene every
/// engine of the command renders. A scale other than 1 is said on stderr ("vct: exposure: ...").
Scene load_scene_and_warn(const std::string& path_or_empty, const SceneLoadOptions& options, const VctSettings& s);

/// Applies s.exposure / s.exposure_ev100 to a loaded scene (and says a scale other than 1).
void expose_scene(Scene& scene, const VctSettings& s);

}  // namespace vct::app
