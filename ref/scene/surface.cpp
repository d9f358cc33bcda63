#include "scene/surface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/srgb.h"

namespace vct {

SurfacePoint interpolate_surface(const Scene& scene, uint32_t triangle, float b1, float b2) {
  const uvec3 t = scene.triangles[triangle];
  const float b0 = 1.0f - b1 - b2;
  SurfacePoint p;
  p.triangle = triangle;
  const vec3 &p0 = scene.positions[t.x], &p1 = scene.positions[t.y], &p2 = scene.positions[t.z];
  p.position = b0 * p0 + b1 * p1 + b2 * p2;
  p.geometric_normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  const vec3 n = b0 * scene.normals[t.x] + b1 * scene.normals[t.y] + b2 * scene.normals[t.z];
  const float len = glm::length(n);
  p.normal = len > 0.0f ? n / len : p.geometric_normal;
  if (!scene.tangents.empty()) {
    const vec4 tg = b0 * scene.tangents[t.x] + b1 * scene.tangents[t.y] + b2 * scene.tangents[t.z];
    p.tangent = vec4(vec3(tg), scene.tangents[t.x].w < 0.0f ? -1.0f : 1.0f);
  }
  if (!scene.uv0.empty()) p.uv0 = b0 * scene.uv0[t.x] + b1 * scene.uv0[t.y] + b2 * scene.uv0[t.z];
  if (!scene.uv1.empty()) p.uv1 = b0 * scene.uv1[t.x] + b1 * scene.uv1[t.y] + b2 * scene.uv1[t.z];
  return p;
}

namespace {

int wrap_index(int i, int size, Wrap mode) {
  if (i >= 0 && i < size) return i;  // every mode leaves texels inside the image alone
  switch (mode) {
    case Wrap::ClampToEdge:
      return std::clamp(i, 0, size - 1);
    case Wrap::MirroredRepeat: {
      const int period = 2 * size;
      int m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case Wrap::Repeat:
    default:
      return ((i % size) + size) % size;
  }
}

/// srgb_to_linear(i / 255) for every 8-bit value, by the same expression: a texel fetch costs a
/// table lookup instead of a pow per channel, with identical bits.
const std::array<float, 256>& srgb8_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgb_to_linear(float(i) / 255.0f);
    return t;
  }();
  return table;
}

vec4 fetch(const Texture& tex, int x, int y, bool srgb) {
  const uint8_t* px = &tex.rgba8[(size_t(y) * size_t(tex.width) + size_t(x)) * 4];
  if (srgb) {
    const std::array<float, 256>& lut = srgb8_to_linear_table();
    return vec4(lut[px[0]], lut[px[1]], lut[px[2]], px[3] / 255.0f);
  }
  return vec4(px[0] / 255.0f, px[1] / 255.0f, px[2] / 255.0f, px[3] / 255.0f);
}

vec4 sample_ref(const Scene& scene, const TextureRef& ref, const SurfacePoint& p, bool srgb) {
  const Texture& tex = scene.textures[size_t(ref.texture)];
  vec2 uv = ref.texcoord == 1 ? p.uv1 : p.uv0;
  if (!ref.transform.is_identity()) uv = ref.transform.apply(uv);
  return sample_texture(tex, uv, srgb);
}

}  // namespace

vec4 sample_texture(const Texture& tex, vec2 uv, bool srgb) {
  if (tex.width <= 0 || tex.height <= 0) return vec4(1.0f);
  // GL: texel i covers [i, i+1) in texel units, its centre at i + 0.5.
  const float u = uv.x * float(tex.width) - 0.5f, v = uv.y * float(tex.height) - 0.5f;
  if (tex.mag_filter == Filter::Nearest) {
    const int x = wrap_index(int(std::floor(uv.x * float(tex.width))), tex.width, tex.wrap_s);
    const int y = wrap_index(int(std::floor(uv.y * float(tex.height))), tex.height, tex.wrap_t);
    return fetch(tex, x, y, srgb);
  }
  const float fu = std::floor(u), fv = std::floor(v);
  const float au = u - fu, av = v - fv;
  const int x0 = wrap_index(int(fu), tex.width, tex.wrap_s), x1 = wrap_index(int(fu) + 1, tex.width, tex.wrap_s);
  const int y0 = wrap_index(int(fv), tex.height, tex.wrap_t), y1 = wrap_index(int(fv) + 1, tex.height, tex.wrap_t);
  return (1.0f - av) * ((1.0f - au) * fetch(tex, x0, y0, srgb) + au * fetch(tex, x1, y0, srgb)) +
         av * ((1.0f - au) * fetch(tex, x0, y1, srgb) + au * fetch(tex, x1, y1, srgb));
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

SurfaceMaterial evaluate_material(const Scene& scene, const SurfacePoint& p) {
  const Material& m = scene.materials[scene.triangle_material[p.triangle]];
  SurfaceMaterial s;
  vec4 base = m.base_color_factor;
  if (m.base_color_texture.present()) base *= sample_ref(scene, m.base_color_texture, p, true);
  s.albedo = vec3(base);
  s.opacity = base.a;
  s.metallic = m.metallic_factor;
  s.roughness = m.roughness_factor;
  if (m.metallic_roughness_texture.present()) {
    const vec4 mr = sample_ref(scene, m.metallic_roughness_texture, p, false);
    s.roughness *= mr.g;  // glTF: G = roughness, B = metallic
    s.metallic *= mr.b;
  }
  s.specular_factor = m.specular_factor;
  s.specular_color = m.specular_color_factor;
  s.emission = m.emission();
  if (m.emissive_texture.present()) s.emission *= vec3(sample_ref(scene, m.emissive_texture, p, true));
  s.shading_normal = p.normal;
  if (m.normal_texture.present()) {
    const vec4 texel = sample_ref(scene, m.normal_texture, p, false);
    vec3 tn(texel.x * 2.0f - 1.0f, texel.y * 2.0f - 1.0f, texel.z * 2.0f - 1.0f);
    if (m.normal_two_channel) tn.z = std::sqrt(std::max(0.0f, 1.0f - tn.x * tn.x - tn.y * tn.y));
    s.shading_normal = apply_normal_map(p.normal, p.tangent, tn, m.normal_scale);
  }
  return s;
}

}  // namespace vct
