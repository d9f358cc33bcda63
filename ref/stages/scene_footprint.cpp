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
  f.particles = !scene.emitters.empty();
  // In units of the voxel volume's edge, so one sum serves every grid (core/steiner_count.h).
  for (const uvec3& t : scene.triangles) {
    const auto at = [&](uint32_t i) { return glm::dvec3(scene.volume.to_texture(scene.positions[i])); };
    const SteinerTerms one = steiner_terms(at(t.x), at(t.y), at(t.z));
    f.fragment_terms.projected_area += one.projected_area;
    f.fragment_terms.extent += one.extent;
  }
  return f;
}

}  // namespace vct
