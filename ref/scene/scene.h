// The scene every engine reads: flattened to world space, immutable after loading.
// Conventions (units, light models, volume placement, particle schema): docs/scenes.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace vct {

/// KHR_texture_transform: uv' = T * R * S * uv (glTF order), applied before sampling.
struct TextureTransform {
  vec2 offset{0.0f};
  float rotation = 0.0f;
  vec2 scale{1.0f};
  bool is_identity() const { return offset == vec2(0.0f) && rotation == 0.0f && scale == vec2(1.0f); }
  vec2 apply(const vec2& uv) const;
};

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
/// GL's magnification filters (glTF sampler magFilter).
enum class Filter { Nearest, Linear };
/// GL's six minification filters (glTF sampler minFilter; GL 4.5 §8.14.2-8.14.3).
enum class MinFilter {
  Nearest,
  Linear,
  NearestMipmapNearest,
  LinearMipmapNearest,
  NearestMipmapLinear,
  LinearMipmapLinear
};

/// One level of a texture's mip chain: RGBA8, row 0 = v = 0, as Texture::rgba8.
struct TextureLevel {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba8;
};

/// A decoded 8-bit texture (RGBA, 4 bytes per texel, row 0 = first row of the file = v=0) with its
/// glTF sampler. The default sampler (a glTF texture without one: glTF leaves it to the
/// implementation) is LINEAR_MIPMAP_LINEAR / LINEAR / REPEAT (docs/scenes.md, "Textures").
struct Texture {
  std::string name;
  int width = 0, height = 0;
  std::vector<uint8_t> rgba8;  // level 0
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  Filter mag_filter = Filter::Linear;
  MinFilter min_filter = MinFilter::LinearMipmapLinear;
  /// Levels 1..q of the mip chain (scene/texture_mips.h), built once from level 0 for each way
  /// the scene's materials read the texture: [0] decoded linear, [1] decoded from sRGB (the box
  /// filter averages in linear light). Empty where not built: sampling then has level 0 only, as
  /// a GL texture allocated with one level.
  std::vector<TextureLevel> mips[2];
};

/// A material slot's texture: which texture, which UV set, which transform. texture < 0: none.
struct TextureRef {
  int texture = -1;
  int texcoord = 0;
  TextureTransform transform;
  bool present() const { return texture >= 0; }
};

/// glTF alphaMode; the values are vct_shared.h's ALPHA_MODE_* (one test for every engine).
enum class AlphaMode { Opaque = 0, Mask = 1, Blend = 2 };

/// glTF metallic-roughness material with the extensions we support.
struct Material {
  std::string name;
  vec4 base_color_factor{1.0f};
  TextureRef base_color_texture;      // sRGB-encoded
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;
  TextureRef metallic_roughness_texture;  // G = roughness, B = metallic (linear)
  TextureRef normal_texture;          // tangent space, linear
  float normal_scale = 1.0f;
  bool normal_two_channel = false;    // RG only, z reconstructed (the seed's compressed form)
  vec3 emissive_factor{0.0f};
  TextureRef emissive_texture;        // sRGB-encoded
  float emissive_strength = 1.0f;     // KHR_materials_emissive_strength
  float specular_factor = 1.0f;       // KHR_materials_specular (0 = pure Lambertian)
  vec3 specular_color_factor{1.0f};
  bool double_sided = false;
  AlphaMode alpha_mode = AlphaMode::Opaque;  // Blend: rendered as Mask at 0.5 (docs/scenes.md)
  float alpha_cutoff = 0.5f;                 // glTF alphaCutoff, used by Mask
  /// Whether a surface point of this material can be discarded by the alpha test.
  bool alpha_tested() const { return alpha_mode != AlphaMode::Opaque; }
  vec3 emission() const { return emissive_factor * emissive_strength; }
  bool is_emissive() const { return emission() != vec3(0.0f); }
};

/// The three KHR_lights_punctual kinds (docs/scenes.md, "Lights"). The values are the shared
/// LIGHT_KIND_* constants of vct_shared.h, so the GL uniform is the enum itself.
enum class LightKind { Spot = 0, Point = 1, Directional = 2 };

/// A KHR_lights_punctual light in world space. Intensity: candela for spot and point lights, lux
/// for a directional light (glTF model), or a unitless scale (seed model); see docs/scenes.md.
/// A directional light uses only `direction` (its position is where its node sits, kept for
/// `vct info`); cone angles matter only for a spot light.
struct Light {
  std::string name;
  LightKind kind = LightKind::Spot;
  vec3 position{0.0f};
  vec3 direction{0.0f, 0.0f, -1.0f};  // unit, where the light points (spot axis, sun direction)
  vec3 color{1.0f};
  float intensity = 1.0f;
  float inner_cone_angle = 0.0f;       // radians
  float outer_cone_angle = 0.7853982f; // radians, <= pi/2
  float range = 0.0f;                  // 0 = infinite; ignored for a directional light
  bool is_spot() const { return kind == LightKind::Spot; }
  bool is_point() const { return kind == LightKind::Point; }
  bool is_directional() const { return kind == LightKind::Directional; }
};

/// "spot", "point", "directional" (the names glTF's KHR_lights_punctual uses).
const char* light_kind_name(LightKind kind);

/// A glTF camera. Perspective (yfov) or orthographic (ymag: half the view's height in metres; the
/// width follows the image's aspect ratio, docs/scenes.md "Cameras").
struct Camera {
  vec3 position{0.0f};
  vec3 forward{0.0f, 0.0f, -1.0f};
  vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = 0.8f;  // radians
  bool orthographic = false;
  float ymag = 1.0f;  // orthographic only
  float aspect_ratio = 0.0f;  // glTF perspective aspectRatio (width / height); 0 = the file has none
  float znear = 0.01f;
  float zfar = 100.0f;
  bool from_file = false;
  mat4 view() const;
  mat4 projection(float aspect) const;  // GL clip space, depth in [-1,1]
  /// Unit vector from world point `p` towards the eye: to the camera position in perspective, the
  /// reverse of the view direction in an orthographic view (every view ray is parallel).
  vec3 to_eye(const vec3& p) const;
};

/// Fire emitter from a node's extras.vct_particles (schema: docs/scenes.md).
struct ParticleEmitter {
  std::string name;
  vec3 origin{0.0f};         // world space
  int count = 256;
  float lifetime = 1.0f;     // seconds; particle i is born at i/count*lifetime (mod lifetime)
  vec3 spawn_extent{0.1f};   // half-size of the spawn box
  vec3 velocity_min{0.0f, 0.5f, 0.0f}, velocity_max{0.0f, 1.0f, 0.0f};
  vec3 acceleration{0.0f, 0.5f, 0.0f};
  vec3 color_start{4.0f, 2.0f, 0.5f}, color_end{1.0f, 0.1f, 0.0f};  // linear radiance
  float size_start = 0.05f, size_end = 0.01f;  // world-space radius
};

/// The voxel volume: a cube [origin, origin+size]^3 mapped to texture coordinates [0,1]^3.
struct VoxelVolume {
  vec3 origin{0.0f};
  float size = 1.0f;
  bool overridden = false;
  vec3 to_texture(const vec3& world) const { return (world - origin) / size; }
  vec3 to_world(const vec3& tex) const { return origin + tex * size; }
};

struct LoadStats {
  int64_t degenerate_triangles_dropped = 0;
  int64_t non_triangle_primitives_skipped = 0;
  std::vector<std::string> warnings;
};

/// The exposure the scene's sources were multiplied by (scene/exposure.h); "none" and 1 as loaded.
struct ExposureApplied {
  std::string mode = "none";   // auto | ev100 | none
  double key_illuminance = 0;  // lux, the auto meter's reading (scene/exposure.h)
  double ev100 = 0;            // the camera's EV100 (auto: the meter's, before rounding and dead band)
  int stops = 0;               // auto: the whole stops applied (scale = 2^stops)
  float scale = 1.0f;          // what every light, emission and particle colour was multiplied by
};

struct Scene {
  std::string source;  // file path or "builtin:default"

  // Vertex attributes, one entry per vertex, world space.
  std::vector<vec3> positions;
  std::vector<vec3> normals;   // unit
  std::vector<vec4> tangents;  // xyz unit, w = handedness (+1/-1)
  std::vector<vec2> uv0, uv1;  // uv1 empty if no primitive has TEXCOORD_1
  std::vector<vec4> colors;    // COLOR_0, linear RGBA; empty if no primitive has it (= white)
  // Triangles: three vertex indices and a material index each.
  std::vector<uvec3> triangles;
  std::vector<uint32_t> triangle_material;

  std::vector<Material> materials;  // always at least one (the glTF default material)
  std::vector<Texture> textures;
  std::vector<Light> lights;
  std::vector<ParticleEmitter> emitters;
  Camera camera;
  VoxelVolume volume;
  Bounds3 bounds;
  LoadStats stats;
  ExposureApplied exposure;

  size_t triangle_count() const { return triangles.size(); }
};

/// Fits the default voxel cube around `bounds`: the largest extent plus a margin of 2 % and
/// at least one voxel of the coarsest grid, centred (docs/scenes.md).
VoxelVolume fit_volume(const Bounds3& bounds);

/// A camera framing `bounds` from +z, used when the file has none.
Camera default_camera(const Bounds3& bounds);

}  // namespace vct
