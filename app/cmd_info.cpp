// vct info SCENE: a summary of what the loader made of the file.
#include <cstdio>

#include "commands.h"
#include "scene/gltf_loader.h"

namespace vct::app {

void register_info(CLI::App& app, int& exit_code) {
  auto* scene_path = new std::string;  // lives as long as the process (CLI11 binds by reference)
  CLI::App* cmd = app.add_subcommand("info", "Print a summary of a glTF scene (no SCENE = built-in default)");
  cmd->add_option("scene", *scene_path, "glTF 2.0 file (.gltf or .glb)");
  cmd->callback([scene_path, &exit_code]() {
    const Scene scene = load_scene(*scene_path);
    std::printf("scene: %s\ntriangles: %zu\nvertices: %zu\nmaterials: %zu\nspot lights: %zu\n",
                scene.source.c_str(), scene.triangle_count(), scene.positions.size(), scene.materials.size(),
                scene.spot_lights.size());
    exit_code = 0;
  });
}

}  // namespace vct::app
