// glTF materials and textures into the Scene model: metallic-roughness, normal map (+ our
// two-channel flag), emission (+ KHR_materials_emissive_strength), KHR_materials_specular and
// KHR_texture_transform on every texture slot, alphaMode and alphaCutoff. Conventions:
// docs/scenes.md.
#include <cmath>

#include "scene/gltf_internal.h"

namespace vct::gltf {
namespace {

float number(const tinygltf::Value& obj, const char* key, float fallback) {
  if (!obj.IsObject() || !obj.Has(key)) return fallback;
  const auto& v = obj.Get(key);
  return v.IsNumber() ? static_cast<float>(v.GetNumberAsDouble()) : fallback;
}

vec2 vec2_of(const tinygltf::Value& obj, const char* key, vec2 fallback) {
  if (!obj.IsObject() || !obj.Has(key)) return fallback;
  const auto& v = obj.Get(key);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber()) return fallback;
  return vec2(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
}

void require_finite(const Context& ctx, const std::string& owner, std::initializer_list<float> values) {
  for (float v : values) {
    if (!std::isfinite(v)) fail(ctx, owner + " has a non-finite factor");
  }
}

TextureRef texture_ref(const Context& ctx, int index, int texcoord, const tinygltf::ExtensionMap& ext,
                       const std::string& owner) {
  TextureRef r;
  r.texture = index;
  r.texcoord = texcoord;
  auto it = ext.find("KHR_texture_transform");
  if (it != ext.end()) {
    const auto& t = it->second;
    r.transform.offset = vec2_of(t, "offset", vec2(0.0f));
    r.transform.rotation = number(t, "rotation", 0.0f);
    r.transform.scale = vec2_of(t, "scale", vec2(1.0f));
    if (t.Has("texCoord") && t.Get("texCoord").IsInt()) r.texcoord = t.Get("texCoord").Get<int>();
    require_finite(ctx, owner + " KHR_texture_transform",
                   {r.transform.offset.x, r.transform.offset.y, r.transform.rotation, r.transform.scale.x,
                    r.transform.scale.y});
  }
  if (index >= 0 && (r.texcoord < 0 || r.texcoord > 1)) {
    fail(ctx, owner + " uses TEXCOORD_" + std::to_string(r.texcoord) + "; only TEXCOORD_0 and TEXCOORD_1 are supported");
  }
  return r;
}

TextureRef texture_ref(const Context& ctx, const tinygltf::TextureInfo& t, const std::string& owner) {
  return texture_ref(ctx, t.index, t.texCoord, t.extensions, owner);
}

Wrap wrap_of(int gl) {
  if (gl == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Wrap::ClampToEdge;
  if (gl == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Wrap::MirroredRepeat;
  return Wrap::Repeat;
}

// glTF leaves an absent minFilter (or a texture without a sampler) to the implementation; ours is
// LINEAR_MIPMAP_LINEAR, what engines use for material textures (docs/scenes.md, "Textures").
MinFilter min_filter_of(int gl) {
  switch (gl) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      return MinFilter::Nearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      return MinFilter::Linear;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      return MinFilter::NearestMipmapNearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      return MinFilter::LinearMipmapNearest;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      return MinFilter::NearestMipmapLinear;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
    default:
      return MinFilter::LinearMipmapLinear;
  }
}

// tinygltf decodes to 8 or 16 bits with 1..4 channels; the Scene keeps RGBA8.
std::vector<uint8_t> to_rgba8(const tinygltf::Image& img) {
  const size_t texels = size_t(img.width) * size_t(img.height);
  const size_t bytes = img.bits == 16 ? 2 : 1;
  std::vector<uint8_t> out(texels * 4, 255);
  for (size_t i = 0; i < texels; ++i) {
    for (int c = 0; c < img.component; ++c) {
      // 16-bit: the high byte (little-endian storage from stb).
      const size_t at = (i * size_t(img.component) + size_t(c)) * bytes + (bytes - 1);
      const uint8_t v = img.image[at];
      if (img.component <= 2 && c == 0) {
        out[i * 4 + 0] = out[i * 4 + 1] = out[i * 4 + 2] = v;  // grey (+ alpha)
      } else if (img.component == 2) {
        out[i * 4 + 3] = v;
      } else {
        out[i * 4 + size_t(c)] = v;
      }
    }
  }
  return out;
}

// glTF gives metallicFactor and roughnessFactor in [0, 1]; engines clamp a value outside it in the
// shader, so we clamp too, and say which value is used (docs/scenes.md, "What the loader refuses").
float factor_in_unit_range(double value, const std::string& what, std::vector<std::string>& warnings) {
  if (value >= 0.0 && value <= 1.0) return float(value);
  const float used = value < 0.0 ? 0.0f : 1.0f;
  warnings.push_back(what + " " + std::to_string(value) + " is outside [0, 1]; using " + std::to_string(int(used)));
  return used;
}

// glTF 2.0 §3.9.4 / material.schema.json: alphaMode is OPAQUE (default), MASK or BLEND;
// alphaCutoff (default 0.5) is >= 0. BLEND is rendered as MASK at 0.5 (docs/scenes.md).
void read_alpha_mode(const Context& ctx, const tinygltf::Material& g, const std::string& owner,
                     Material& mat, std::vector<std::string>& warnings) {
  if (g.alphaMode == "OPAQUE" || g.alphaMode.empty()) {
    mat.alpha_mode = AlphaMode::Opaque;
  } else if (g.alphaMode == "MASK") {
    mat.alpha_mode = AlphaMode::Mask;
  } else if (g.alphaMode == "BLEND") {
    mat.alpha_mode = AlphaMode::Blend;
    warnings.push_back(
        owner + ": alphaMode BLEND is rendered as MASK with alphaCutoff 0.5 in every engine");
  } else {
    fail(ctx, owner + ": alphaMode \"" + g.alphaMode + "\" is not OPAQUE, MASK or BLEND");
  }
  mat.alpha_cutoff = float(g.alphaCutoff);
  if (!std::isfinite(mat.alpha_cutoff) || mat.alpha_cutoff < 0.0f)
    fail(ctx, owner + ": alphaCutoff must be a finite number >= 0");
}

}  // namespace

void convert_textures(const Context& ctx, Scene& scene) {
  const auto& m = ctx.model;
  for (size_t i = 0; i < m.textures.size(); ++i) {
    const auto& t = m.textures[i];
    const auto& img = m.images[static_cast<size_t>(t.source)];
    const std::string label = "image " + std::to_string(t.source) + (img.uri.empty() ? "" : " '" + img.uri + "'");
    if (img.image.empty() || img.width <= 0 || img.height <= 0) {
      fail(ctx, label + " (texture " + std::to_string(i) + ") could not be loaded (missing file or undecodable image)");
    }
    const size_t need = size_t(img.width) * size_t(img.height) * size_t(img.component) * (img.bits == 16 ? 2u : 1u);
    if (img.component < 1 || img.component > 4 || (img.bits != 8 && img.bits != 16) || img.image.size() < need) {
      fail(ctx, label + " has an unsupported pixel layout");
    }
    Texture out;
    out.name = !t.name.empty() ? t.name : (!img.name.empty() ? img.name : img.uri);
    out.width = img.width;
    out.height = img.height;
    out.rgba8 = to_rgba8(img);
    if (t.sampler >= 0) {
      const auto& s = m.samplers[static_cast<size_t>(t.sampler)];
      out.wrap_s = wrap_of(s.wrapS);
      out.wrap_t = wrap_of(s.wrapT);
      out.mag_filter = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
      out.min_filter = min_filter_of(s.minFilter);
    }
    scene.textures.push_back(std::move(out));
  }
}

void convert_materials(const Context& ctx, Scene& scene) {
  for (size_t i = 0; i < ctx.model.materials.size(); ++i) {
    const auto& g = ctx.model.materials[i];
    const std::string owner = "material " + std::to_string(i) + (g.name.empty() ? "" : " '" + g.name + "'");
    const auto& pbr = g.pbrMetallicRoughness;
    Material mat;
    mat.name = g.name.empty() ? "material_" + std::to_string(i) : g.name;
    if (pbr.baseColorFactor.size() == 4) {
      mat.base_color_factor = vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                   float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
    }
    mat.base_color_texture = texture_ref(ctx, pbr.baseColorTexture, owner + " baseColorTexture");
    mat.metallic_factor = factor_in_unit_range(pbr.metallicFactor, owner + " metallicFactor", scene.stats.warnings);
    mat.roughness_factor = factor_in_unit_range(pbr.roughnessFactor, owner + " roughnessFactor", scene.stats.warnings);
    mat.metallic_roughness_texture = texture_ref(ctx, pbr.metallicRoughnessTexture, owner + " metallicRoughnessTexture");
    mat.normal_texture = texture_ref(ctx, g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions,
                                     owner + " normalTexture");
    mat.normal_scale = float(g.normalTexture.scale);
    if (g.extras.IsObject() && g.extras.Has("vct_normal_two_channel")) {
      const auto& v = g.extras.Get("vct_normal_two_channel");
      if (!v.IsBool()) fail(ctx, owner + ": extras.vct_normal_two_channel must be true or false");
      mat.normal_two_channel = v.Get<bool>();
    }
    if (g.emissiveFactor.size() == 3) {
      mat.emissive_factor = vec3(float(g.emissiveFactor[0]), float(g.emissiveFactor[1]), float(g.emissiveFactor[2]));
    }
    mat.emissive_texture = texture_ref(ctx, g.emissiveTexture, owner + " emissiveTexture");
    auto es = g.extensions.find("KHR_materials_emissive_strength");
    if (es != g.extensions.end()) mat.emissive_strength = number(es->second, "emissiveStrength", 1.0f);
    auto sp = g.extensions.find("KHR_materials_specular");
    if (sp != g.extensions.end()) {
      mat.specular_factor = number(sp->second, "specularFactor", 1.0f);
      const auto& obj = sp->second;
      if (obj.Has("specularColorFactor") && obj.Get("specularColorFactor").IsArray() &&
          obj.Get("specularColorFactor").ArrayLen() == 3) {
        const auto& c = obj.Get("specularColorFactor");
        mat.specular_color_factor = vec3(float(c.Get(0).GetNumberAsDouble()), float(c.Get(1).GetNumberAsDouble()),
                                         float(c.Get(2).GetNumberAsDouble()));
      }
      if (obj.Has("specularTexture") || obj.Has("specularColorTexture")) {
        scene.stats.warnings.push_back(owner + ": KHR_materials_specular textures are ignored (factors only)");
      }
    }
    if (g.occlusionTexture.index >= 0) scene.stats.warnings.push_back(owner + ": occlusionTexture is ignored");
    warn_material_extensions(g, owner, scene.stats.warnings);
    read_alpha_mode(ctx, g, owner, mat, scene.stats.warnings);
    mat.double_sided = g.doubleSided;
    const vec4 b = mat.base_color_factor;
    const vec3 e = mat.emissive_factor, sc = mat.specular_color_factor;
    require_finite(ctx, owner, {b.x, b.y, b.z, b.w, mat.metallic_factor, mat.roughness_factor, mat.normal_scale, e.x, e.y,
                                e.z, mat.emissive_strength, mat.specular_factor, sc.x, sc.y, sc.z});
    if (mat.emissive_strength < 0.0f) fail(ctx, owner + ": emissiveStrength must be >= 0");
    scene.materials.push_back(std::move(mat));
  }
}

}  // namespace vct::gltf
