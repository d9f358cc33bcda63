// glTF 2.0 (.gltf / .glb) into the flat Scene model. Every problem with the file is an
// InputError naming the file and what is wrong (see tests/ref/gltf_loader_test.cpp).
#pragma once

#include <string>

#include "scene/scene.h"

namespace vct {

/// Loads a .gltf or .glb file.
Scene load_gltf_file(const std::string& path);

/// Loads glTF JSON held in memory; `name` is used in messages; external URIs resolve in base_dir.
Scene load_gltf_text(const std::string& json_text, const std::string& name, const std::string& base_dir);

/// The scene argument of the command line: empty = the built-in default scene (the Cornell box
/// of scenes/cornell_box.gltf, embedded in the binary), otherwise a file path.
Scene load_scene(const std::string& path_or_empty);

/// Name shown for the built-in scene.
constexpr const char* kBuiltinSceneName = "builtin:cornell_box";

}  // namespace vct
