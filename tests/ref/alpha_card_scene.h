// The hand-computable alpha-mask case every engine's test uses (ref, pt, gl): a 2 m x 2 m card in
// the plane z = 0 (x, y in [-1, 1], front face +z) whose base-colour texture is 2 x 1 texels,
// alpha 0 on the left and 1 on the right, LINEAR, CLAMP_TO_EDGE, u = (x + 1) / 2. Bilinear alpha
// is clamp((u - 1/4) / (1/2), 0, 1), so with alphaCutoff 1/2 exactly the right half (x >= 0)
// stays: every pass must see only the right half. Optionally a backdrop at z = -1 (6 m x 6 m,
// opaque) so that what lies behind a cut-away point shows.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "scene/scene.h"
#include "stage_test_scene.h"

namespace vct::test {

inline void add_card_quad(Scene& s, float z, float half, uint32_t material) {
  const uint32_t base = uint32_t(s.positions.size());
  const vec2 corners[4] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  for (const vec2& c : corners) {
    s.positions.push_back(vec3(c, z));
    s.normals.push_back(vec3(0.0f, 0.0f, 1.0f));
    s.tangents.push_back(vec4(1.0f, 0.0f, 0.0f, 1.0f));
    s.uv0.push_back(vec2((c.x / half + 1.0f) * 0.5f, (1.0f - c.y / half) * 0.5f));
    s.bounds.add(vec3(c, z));
  }
  s.triangles.push_back(uvec3(base, base + 1, base + 2));
  s.triangles.push_back(uvec3(base, base + 2, base + 3));
  s.triangle_material.push_back(material);
  s.triangle_material.push_back(material);
}

/// A 2 x 1 texture (left texel, right texel: RGBA8 each), CLAMP_TO_EDGE, LINEAR unless `nearest`.
inline Texture two_texel_texture(const std::string& name, std::array<uint8_t, 8> rgba8, bool nearest = false) {
  Texture t;
  t.name = name;
  t.width = 2;
  t.height = 1;
  t.rgba8.assign(rgba8.begin(), rgba8.end());
  t.wrap_s = t.wrap_t = Wrap::ClampToEdge;
  if (nearest) t.mag_filter = Filter::Nearest, t.min_filter = MinFilter::Nearest;
  return t;
}

/// Material 0: the card (albedo 0.5, alpha_mode, cutoff); material 1: the backdrop (albedo 0.8).
inline Scene half_masked_card(bool backdrop, AlphaMode mode = AlphaMode::Mask,
                              float cutoff = 0.5f) {
  Scene s;
  s.source = "test:half_masked_card";
  s.textures.push_back(two_texel_texture("left_transparent", {128, 128, 128, 0, 128, 128, 128, 255}));
  Material card;
  card.name = "card";
  card.base_color_factor = vec4(1.0f);
  card.base_color_texture.texture = 0;
  card.metallic_factor = 0.0f;
  card.roughness_factor = 1.0f;
  card.specular_factor = 0.0f;
  card.double_sided = true;
  card.alpha_mode = mode;
  card.alpha_cutoff = cutoff;
  s.materials.push_back(card);
  Material back;
  back.name = "backdrop";
  back.base_color_factor = vec4(0.8f, 0.8f, 0.8f, 1.0f);
  back.metallic_factor = 0.0f;
  back.specular_factor = 0.0f;
  back.double_sided = true;
  s.materials.push_back(back);
  add_card_quad(s, 0.0f, 1.0f, 0);
  if (backdrop) add_card_quad(s, -1.0f, 3.0f, 1);
  s.volume = fit_volume(s.bounds);
  front_camera(s, vec3(0.0f, 0.0f, 3.0f), 0.9f, 0.1f);
  return s;
}

/// Which surface a world point on the card's plane should show: the card where x >= 0 (with
/// |y| <= 1), nothing of the card elsewhere. `margin` leaves out points within that distance of
/// the alpha edge x = 0 or the card's border, where a sample position's rounding decides.
enum class CardSide { Kept, CutAway, Undecided };
inline CardSide card_side(float x, float y, float margin) {
  if (std::abs(x) < margin || std::abs(std::abs(x) - 1.0f) < margin ||
      std::abs(std::abs(y) - 1.0f) < margin)
    return CardSide::Undecided;
  if (std::abs(x) > 1.0f || std::abs(y) > 1.0f) return CardSide::CutAway;  // off the card
  return x > 0.0f ? CardSide::Kept : CardSide::CutAway;
}

}  // namespace vct::test
