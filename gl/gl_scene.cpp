#include "gl_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "gl_context.h"
#include "gl_setting_uniforms.h"
#include "shared/vct_shared.h"
#include "scene/texture_mips.h"

namespace vct::gl {
namespace {

struct Vertex {
  float position[3];
  float normal[3];
  float tangent[4];
  float uv0[2];
  float uv1[2];
  float color[4];  // COLOR_0, white without it
};

GLint wrap_mode(Wrap w) {
  switch (w) {
    case Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case Wrap::Repeat:
    default: return GL_REPEAT;
  }
}

GLint min_filter_mode(MinFilter f) {
  switch (f) {
    case MinFilter::Nearest:
      return GL_NEAREST;
    case MinFilter::Linear:
      return GL_LINEAR;
    case MinFilter::NearestMipmapNearest:
      return GL_NEAREST_MIPMAP_NEAREST;
    case MinFilter::LinearMipmapNearest:
      return GL_LINEAR_MIPMAP_NEAREST;
    case MinFilter::NearestMipmapLinear:
      return GL_NEAREST_MIPMAP_LINEAR;
    case MinFilter::LinearMipmapLinear:
    default:
      return GL_LINEAR_MIPMAP_LINEAR;
  }
}

mat3 transform_matrix(const TextureTransform& t) {
  // uv' = R S uv + offset, as TextureTransform::apply (columns of a GLSL mat3 acting on (u,v,1)).
  const float c = std::cos(t.rotation), s = std::sin(t.rotation);
  mat3 m(1.0f);
  m[0] = vec3(c * t.scale.x, -s * t.scale.x, 0.0f);
  m[1] = vec3(s * t.scale.y, c * t.scale.y, 0.0f);
  m[2] = vec3(t.offset, 1.0f);
  return m;
}

}  // namespace

GlScene::GlScene(const Scene& scene) : scene_(scene) {
  std::vector<Vertex> vertices(scene.positions.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    Vertex& v = vertices[i];
    const vec3 p = scene.positions[i];
    const vec3 n = i < scene.normals.size() ? scene.normals[i] : vec3(0.0f, 0.0f, 1.0f);
    const vec4 t = i < scene.tangents.size() ? scene.tangents[i] : vec4(1.0f, 0.0f, 0.0f, 1.0f);
    const vec2 a = i < scene.uv0.size() ? scene.uv0[i] : vec2(0.0f);
    const vec2 b = i < scene.uv1.size() ? scene.uv1[i] : vec2(0.0f);
    const vec4 col = i < scene.colors.size() ? scene.colors[i] : vec4(1.0f);
    for (int c = 0; c < 3; ++c) v.position[c] = p[c], v.normal[c] = n[c];
    for (int c = 0; c < 4; ++c) v.tangent[c] = t[c];
    for (int c = 0; c < 2; ++c) v.uv0[c] = a[c], v.uv1[c] = b[c];
    for (int c = 0; c < 4; ++c) v.color[c] = col[c];
  }
  // Indices grouped by material, triangles in scene order within a material (stable), so draw
  // order is deterministic.
  std::vector<uint32_t> order(scene.triangles.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return scene.triangle_material[a] < scene.triangle_material[b];
  });
  std::vector<uint32_t> indices;
  indices.reserve(order.size() * 3);
  for (uint32_t t : order) {
    const uint32_t m = scene.triangle_material[t];
    if (ranges_.empty() || ranges_.back().material != m)
      ranges_.push_back({m, GLsizei(indices.size()), 0});
    for (int c = 0; c < 3; ++c) indices.push_back(scene.triangles[t][c]);
    ranges_.back().count += 3;
  }
  index_count_ = GLsizei(indices.size());
  glCreateBuffers(1, &vbo_);
  glNamedBufferStorage(vbo_, GLsizeiptr(std::max<size_t>(vertices.size(), 1) * sizeof(Vertex)),
                       vertices.empty() ? nullptr : vertices.data(), 0);
  glCreateBuffers(1, &ibo_);
  glNamedBufferStorage(ibo_, GLsizeiptr(std::max<size_t>(indices.size(), 1) * 4),
                       indices.empty() ? nullptr : indices.data(), 0);
  glCreateVertexArrays(1, &vao_);
  glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao_, ibo_);
  // Attribute locations as scene.vert / voxelize.vert declare them.
  const GLint sizes[6] = {3, 3, 4, 2, 2, 4};
  const GLuint offsets[6] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, tangent),
                             offsetof(Vertex, uv0),      offsetof(Vertex, uv1),    offsetof(Vertex, color)};
  for (GLuint a = 0; a < 6; ++a) {
    glEnableVertexArrayAttrib(vao_, a);
    glVertexArrayAttribFormat(vao_, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao_, a, 0);
  }
  for (const Material& m : scene.materials) alpha_tested_ = alpha_tested_ || m.alpha_tested();
  const uint8_t white[4] = {255, 255, 255, 255};
  glCreateTextures(GL_TEXTURE_2D, 1, &white_);
  glTextureStorage2D(white_, 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(white_, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  check_gl("scene upload");
}

GLuint GlScene::texture(int index, bool srgb) {
  const auto key = std::make_pair(index, srgb);
  const auto it = textures_.find(key);
  if (it != textures_.end()) return it->second;
  const Texture& tex = scene_.textures[size_t(index)];
  // Every level the CPU built for this encoding (scene/texture_mips.h), uploaded as is: GL and the
  // CPU then filter identical bits; glGenerateMipmap's filter is the driver's own.
  const int levels = available_levels(tex, srgb);
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, tex.width, tex.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int level = 0; level < levels; ++level) {
    int w = 0, h = 0;
    const uint8_t* texels = mip_level_texels(tex, srgb, level, w, h);
    // Row 0 is v = 0, which is also GL's t = 0 row: no flip.
    glTextureSubImage2D(t, level, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  }
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, min_filter_mode(tex.min_filter));
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER,
                      tex.mag_filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, wrap_mode(tex.wrap_s));
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, wrap_mode(tex.wrap_t));
  textures_[key] = t;
  return t;
}

void GlScene::bind_material(const Program& p, const Material& m) {
  p.set("u_base_color_factor", m.base_color_factor);
  p.set("u_metallic_factor", m.metallic_factor);
  p.set("u_roughness_factor", m.roughness_factor);
  p.set("u_normal_scale", m.normal_scale);
  p.set("u_normal_two_channel", m.normal_two_channel ? 1 : 0);
  p.set("u_emission", m.emission());
  p.set("u_specular_factor", m.specular_factor);
  p.set("u_specular_color", m.specular_color_factor);
  p.set("u_alpha_mode", int(m.alpha_mode));  // AlphaMode's values are vct_shared.h's ALPHA_MODE_*
  p.set("u_alpha_cutoff", m.alpha_cutoff);
  // Without COLOR_0 the attribute is a constant white, which interpolation need not return as
  // exactly 1: the shaders skip the product then, as the CPU multiplies by an exact 1.
  p.set("u_vertex_colors", scene_.colors.empty() ? 0 : 1);
  const TextureRef* refs[4] = {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
                               &m.emissive_texture};
  const bool srgb[4] = {true, false, false, true};
  for (int slot = 0; slot < 4; ++slot) {
    const TextureRef& r = *refs[slot];
    const bool present = r.present() && size_t(r.texture) < scene_.textures.size();
    const std::string idx = "[" + std::to_string(slot) + "]";
    p.set(("u_tex_present" + idx).c_str(), present ? 1 : 0);
    p.set(("u_tex_coord" + idx).c_str(), r.texcoord);
    p.set(("u_tex_transform" + idx).c_str(), transform_matrix(r.transform));
    glBindTextureUnit(GLuint(slot), present ? texture(r.texture, srgb[slot]) : white_);
  }
}

void GlScene::draw(const Program& p) {
  glBindVertexArray(vao_);
  for (const DrawRange& r : ranges_) {
    bind_material(p, scene_.materials[r.material]);
    glDrawElements(GL_TRIANGLES, r.count, GL_UNSIGNED_INT, reinterpret_cast<const void*>(size_t(r.first) * 4));
  }
  check_gl("scene draw");
}

void GlScene::draw_depth_only(const Program& p) {
  if (alpha_tested_) {
    draw(p);  // per material: the alpha test needs its uniforms and texture
    return;
  }
  p.set("u_alpha_mode", sh::ALPHA_MODE_OPAQUE);
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  check_gl("depth draw");
}

void GlScene::set_lights(const Program& p, const VctSettings& s, const std::vector<mat4>& layer_view_proj,
                         const std::vector<int>& light_layer) const {
  const int count = std::min<int>(int(scene_.lights.size()), kMaxLights);
  p.set("u_light_count", count);
  p.set("u_light_model", s.light_model == LightModel::Seed ? 1 : 0);
  set_setting_uniforms(p, s);
  for (int i = 0; i < count; ++i) {
    const Light& l = scene_.lights[size_t(i)];
    const std::string idx = "[" + std::to_string(i) + "]";
    p.set(("u_light_kind" + idx).c_str(), int(l.kind));
    p.set(("u_light_position" + idx).c_str(), l.position);
    p.set(("u_light_direction" + idx).c_str(), l.direction);
    p.set(("u_light_color" + idx).c_str(), l.color);
    p.set(("u_light_intensity" + idx).c_str(), l.intensity);
    p.set(("u_light_cos_inner" + idx).c_str(), std::cos(l.inner_cone_angle));
    p.set(("u_light_cos_outer" + idx).c_str(), std::cos(l.outer_cone_angle));
    p.set(("u_light_range" + idx).c_str(), l.range);
    p.set(("u_light_layer" + idx).c_str(), light_layer[size_t(i)]);
  }
  for (size_t l = 0; l < layer_view_proj.size(); ++l)
    p.set(("u_shadow_view_proj[" + std::to_string(l) + "]").c_str(), layer_view_proj[l]);
}

}  // namespace vct::gl
