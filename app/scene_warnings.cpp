#include "scene_warnings.h"

#include <fmt/core.h>

namespace vct::app {

Scene load_scene_and_warn(const std::string& path_or_empty, const SceneLoadOptions& options) {
  Scene scene = load_scene(path_or_empty, options);
  for (const std::string& w : scene.stats.warnings) fmt::print(stderr, "vct: warning: {}: {}\n", scene.source, w);
  return scene;
}

}  // namespace vct::app
