#include "scene/alpha_mask.h"

#include "scene/surface.h"
#include "shared/vct_shared.h"

namespace vct {

// GL passes AlphaMode to alpha_mask.glsl as its integer value.
static_assert(int(AlphaMode::Opaque) == sh::ALPHA_MODE_OPAQUE &&
                  int(AlphaMode::Mask) == sh::ALPHA_MODE_MASK &&
                  int(AlphaMode::Blend) == sh::ALPHA_MODE_BLEND,
              "AlphaMode must match vct_shared.h");

bool triangle_alpha_tested(const Scene& scene, uint32_t triangle) {
  return scene.materials[scene.triangle_material[triangle]].alpha_tested();
}

float base_color_alpha(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  float alpha = m.base_color_factor.a;
  const uvec3 t = scene.triangles[triangle];
  const float b0 = 1.0f - b1 - b2;  // interpolation as interpolate_surface
  const TextureRef& ref = m.base_color_texture;
  if (ref.present()) {
    const std::vector<vec2>& uvs = ref.texcoord == 1 ? scene.uv1 : scene.uv0;
    vec2 uv(0.0f);
    if (!uvs.empty()) uv = b0 * uvs[t.x] + b1 * uvs[t.y] + b2 * uvs[t.z];
    if (!ref.transform.is_identity()) uv = ref.transform.apply(uv);
    alpha *= sample_texture(scene.textures[size_t(ref.texture)], uv, false).a;
  }
  if (!scene.colors.empty()) {
    alpha *= (b0 * scene.colors[t.x] + b1 * scene.colors[t.y] + b2 * scene.colors[t.z]).a;  // COLOR_0
  }
  return alpha;
}

bool surface_masked(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  if (!m.alpha_tested()) return false;
  return sh::alpha_discards(int(m.alpha_mode), base_color_alpha(scene, triangle, b1, b2),
                            m.alpha_cutoff);
}

bool scene_has_alpha_test(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (m.alpha_tested()) return true;
  return false;
}

}  // namespace vct
