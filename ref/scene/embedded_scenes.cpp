#include "scene/embedded_scenes.h"

namespace vct {

const std::string& embedded_scene(const std::string& name) {
  static const std::string none;
  const auto& files = embedded_scene_files();
  const auto it = files.find(name);
  return it == files.end() ? none : it->second;
}

}  // namespace vct
