#include "pt/ray_cone.h"

#include <cmath>

namespace vct::pt {

float pixel_spread_angle(const Camera& camera, int height) {
  return std::atan(2.0f * std::tan(camera.yfov * 0.5f) / float(height));
}

SlotLods ray_cone_lods(const Scene& scene, uint32_t triangle, float t, const vec3& dir,
                       float spread_angle) {
  SlotLods out;
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  const uvec3 tri = scene.triangles[triangle];
  const glm::dvec3 p0(scene.positions[tri.x]), p1(scene.positions[tri.y]),
      p2(scene.positions[tri.z]);
  const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
  const double world_area = glm::length(cross);  // twice the area, as the texel area below
  if (!(world_area > 0.0)) return out;
  const double cos_theta = std::abs(glm::dot(cross / world_area, glm::dvec3(dir)));
  const double width = 2.0 * double(t) * std::tan(double(spread_angle) * 0.5);
  if (!(cos_theta > 0.0) || !(width > 0.0)) return out;
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref || size_t(ref->texture) >= scene.textures.size()) continue;
    const std::vector<vec2>& uv = ref->texcoord == 1 ? scene.uv1 : scene.uv0;
    if (uv.empty()) continue;
    const Texture& tex = scene.textures[size_t(ref->texture)];
    const glm::dvec2 a = glm::dvec2(uv[tri.y]) - glm::dvec2(uv[tri.x]),
                     b = glm::dvec2(uv[tri.z]) - glm::dvec2(uv[tri.x]);
    // The transform's rotation keeps areas; its scale multiplies them by |sx sy|.
    const double scale = std::abs(double(ref->transform.scale.x) * double(ref->transform.scale.y));
    const double texel_area =
        std::abs(a.x * b.y - a.y * b.x) * scale * double(tex.width) * double(tex.height);
    if (!(texel_area > 0.0)) continue;
    out.lambda[slot] = std::log2(width / cos_theta) + 0.5 * std::log2(texel_area / world_area);
  }
  return out;
}

}  // namespace vct::pt
