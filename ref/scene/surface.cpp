#include "scene/surface.h"

#include "io/srgb.h"

#include <algorithm>
#include <cmath>


namespace vct {

vec3 interpolated_position(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const uvec3 t = scene.triangles[triangle];
  const float b0 = 1.0f - b1 - b2;
  return b0 * scene.positions[t.x] + b1 * scene.positions[t.y] + b2 * scene.positions[t.z];
}

SurfacePoint interpolate_position(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const uvec3 t = scene.triangles[triangle];
  SurfacePoint p;
  p.triangle = triangle;
  const vec3 &p0 = scene.positions[t.x], &p1 = scene.positions[t.y], &p2 = scene.positions[t.z];
  p.position = interpolated_position(scene, triangle, b1, b2);
  p.geometric_normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  return p;
}

SurfacePoint interpolate_surface(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const uvec3 t = scene.triangles[triangle];
  const float b0 = 1.0f - b1 - b2;
  SurfacePoint p = interpolate_position(scene, triangle, b1, b2);
  const vec3 n = b0 * scene.normals[t.x] + b1 * scene.normals[t.y] + b2 * scene.normals[t.z];
  const float len = glm::length(n);
  p.normal = len > 0.0f ? n / len : p.geometric_normal;
  if (!scene.tangents.empty()) {
    const vec4 tg = b0 * scene.tangents[t.x] + b1 * scene.tangents[t.y] + b2 * scene.tangents[t.z];
    p.tangent = vec4(vec3(tg), scene.tangents[t.x].w < 0.0f ? -1.0f : 1.0f);
  }
  if (!scene.uv0.empty()) p.uv0 = b0 * scene.uv0[t.x] + b1 * scene.uv0[t.y] + b2 * scene.uv0[t.z];
  if (!scene.uv1.empty()) p.uv1 = b0 * scene.uv1[t.x] + b1 * scene.uv1[t.y] + b2 * scene.uv1[t.z];
  if (!scene.colors.empty()) p.color = b0 * scene.colors[t.x] + b1 * scene.colors[t.y] + b2 * scene.colors[t.z];
  return p;
}

namespace {

vec4 sample_ref(const Scene& scene, const TextureRef& ref, const SurfacePoint& p, bool srgb,
                double lambda, bool srgb_after_filter, vec2 texel_shift) {
  return sample_texture_lod(scene.textures[size_t(ref.texture)], slot_uv(ref, p), srgb, lambda, srgb_after_filter,
                            texel_shift);
}

}  // namespace

vec2 slot_uv(const TextureRef& ref, const SurfacePoint& p) {
  const vec2 uv = ref.texcoord == 1 ? p.uv1 : p.uv0;
  return ref.transform.is_identity() ? uv : ref.transform.apply(uv);
}

const TextureRef* slot_texture(const Material& m, int slot) {
  const TextureRef* refs[kTextureSlots] = {&m.base_color_texture, &m.metallic_roughness_texture,
                                           &m.normal_texture, &m.emissive_texture};
  return refs[slot]->present() ? refs[slot] : nullptr;
}

vec3 apply_normal_map(const vec3& normal, const vec4& tangent, vec3 tn, float scale) {
  tn.x *= scale;
  tn.y *= scale;
  vec3 t = vec3(tangent);
  t = t - normal * glm::dot(normal, t);  // Gram-Schmidt: keep the frame orthogonal
  const float tl = glm::length(t);
  if (tl < 1e-8f) return normal;
  t /= tl;
  const vec3 b = glm::cross(normal, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
  const vec3 n = t * tn.x + b * tn.y + normal * tn.z;
  const float nl = glm::length(n);
  return nl > 1e-8f ? n / nl : normal;
}

vec3 shift_srgb_steps(const vec3& v, float steps) {
  vec3 out;
  for (int c = 0; c < 3; ++c)
    out[c] = srgb_to_linear(std::clamp(linear_to_srgb(std::clamp(v[c], 0.0f, 1.0f)) + steps / 255.0f, 0.0f, 1.0f));
  return out;
}

namespace {
// An sRGB slot's lookup as a GL may decode it (SlotLods::srgb_decode_steps).
vec4 decoded(vec4 v, const SlotLods& lods) {
  if (lods.srgb_decode_steps == 0.0f) return v;
  const vec3 rgb = shift_srgb_steps(vec3(v), lods.srgb_decode_steps);
  return vec4(rgb, v.a);
}
}  // namespace

SurfaceMaterial evaluate_material(const Scene& scene, const SurfacePoint& p, const SlotLods& lods) {
  const Material& m = scene.materials[scene.triangle_material[p.triangle]];
  SurfaceMaterial s;
  vec4 base = m.base_color_factor;
  if (m.base_color_texture.present())
    base *= decoded(sample_ref(scene, m.base_color_texture, p, true, lods.lambda[kSlotBaseColor],
                               lods.srgb_after_filter, lods.texel_shift),
                    lods);
  base *= p.color;  // glTF 2.0 §3.9.2: factor x texture x COLOR_0
  s.albedo = vec3(base);
  s.opacity = base.a;
  s.metallic = m.metallic_factor;
  s.roughness = m.roughness_factor;
  if (m.metallic_roughness_texture.present()) {
    const vec4 mr = sample_ref(scene, m.metallic_roughness_texture, p, false,
                               lods.lambda[kSlotMetallicRoughness], lods.srgb_after_filter, lods.texel_shift);
    s.roughness *= mr.g;  // glTF: G = roughness, B = metallic
    s.metallic *= mr.b;
  }
  s.specular_factor = m.specular_factor;
  s.specular_color = m.specular_color_factor;
  s.emission = m.emission();
  if (m.emissive_texture.present())
    s.emission *= vec3(decoded(sample_ref(scene, m.emissive_texture, p, true, lods.lambda[kSlotEmissive],
                                          lods.srgb_after_filter, lods.texel_shift),
                               lods));
  s.shading_normal = p.normal;
  if (m.normal_texture.present()) {
    const vec4 sampled = sample_ref(scene, m.normal_texture, p, false, lods.lambda[kSlotNormal],
                                    lods.srgb_after_filter, lods.texel_shift);
    const vec3 texel = glm::clamp(vec3(sampled) + lods.normal_texel_offset, vec3(0.0f), vec3(1.0f));
    vec3 tn(texel.x * 2.0f - 1.0f, texel.y * 2.0f - 1.0f, texel.z * 2.0f - 1.0f);
    if (m.normal_two_channel) tn.z = std::sqrt(std::max(0.0f, 1.0f - tn.x * tn.x - tn.y * tn.y));
    s.shading_normal = apply_normal_map(p.normal, p.tangent, tn, m.normal_scale);
  }
  return s;
}

bool material_reads_lods(const Material& m) {
  return m.base_color_texture.present() || m.metallic_roughness_texture.present() || m.normal_texture.present() ||
         m.emissive_texture.present();
}

bool material_reads_srgb_order(const Material& m) {
  return m.base_color_texture.present() || m.emissive_texture.present();
}

}  // namespace vct
