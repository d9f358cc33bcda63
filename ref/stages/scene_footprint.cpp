#include "stages/scene_footprint.h"

#include "scene/alpha_mask.h"
#include "stages/shadow_map.h"

namespace vct {

SceneFootprint scene_footprint(const Scene& scene) {
  SceneFootprint f;
  f.shadow_layers = shadow_map_layers(scene);
  f.triangles = scene.triangles.size();
  for (const Texture& t : scene.textures) {
    f.texture_bytes += t.rgba8.size();
    for (const auto& chain : t.mips)
      for (const TextureLevel& level : chain) f.texture_bytes += level.rgba8.size();
  }
  f.alpha_tested = scene_has_alpha_test(scene);
  return f;
}

}  // namespace vct
