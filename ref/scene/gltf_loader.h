// glTF 2.0 (.gltf / .glb) into the flat Scene model. Every problem with the file is an
// InputError naming the file and what is wrong (see tests/ref/gltf_loader_test.cpp).
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace vct {

/// What a scene may make the loader do (docs/scenes.md, "File access" and "Limits").
struct SceneLoadOptions {
  /// false: every external URI must name a file inside the scene file's folder (no absolute
  /// paths, no '..' leaving it, no file: URIs, no symbolic links out); --allow-outside-scene-dir.
  bool allow_outside_scene_dir = false;
  /// Bytes all decoded textures may take together; 0 = this machine's physical memory.
  uint64_t image_memory_budget = 0;
};

/// The largest file a scene reads (the .gltf/.glb and every buffer or image its URIs name): a GLB
/// records its length in 32 bits and tinygltf takes a document's length as `unsigned int`, so
/// nothing larger can be a glTF file (docs/scenes.md, "Limits").
inline constexpr uint64_t kMaxSceneFileBytes = 0xFFFFFFFFull;

/// Loads a .gltf or .glb file.
Scene load_gltf_file(const std::string& path, const SceneLoadOptions& options = {});

/// Loads glTF JSON held in memory; `name` is used in messages; external URIs resolve in base_dir
/// ("" = the working directory), which is also the folder the file-access policy allows.
Scene load_gltf_text(const std::string& json_text, const std::string& name, const std::string& base_dir,
                     const SceneLoadOptions& options = {});

/// The scene argument of the command line: empty = the built-in default scene (the Cornell box
/// of scenes/cornell_box.gltf, embedded in the binary), otherwise a file path.
Scene load_scene(const std::string& path_or_empty, const SceneLoadOptions& options = {});

/// Name shown for the built-in scene.
constexpr const char* kBuiltinSceneName = "builtin:cornell_box";

}  // namespace vct
