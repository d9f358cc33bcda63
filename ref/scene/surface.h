// A point on a triangle and its textured material: the one definition the G-buffer, voxel light
// injection and the path tracer all use, so they agree on what a surface is.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"
#include "scene/texture_lod.h"
#include "scene/texture_sample.h"

namespace vct {

/// Interpolated vertex attributes at barycentrics (1-b1-b2, b1, b2) of a triangle.
struct SurfacePoint {
  uint32_t triangle = 0;
  vec3 position{0.0f};
  vec3 geometric_normal{0.0f, 0.0f, 1.0f};  // from the winding (v1-v0)x(v2-v0), unit
  vec3 normal{0.0f, 0.0f, 1.0f};            // interpolated vertex normal, unit
  vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};     // interpolated tangent, w = handedness
  vec2 uv0{0.0f}, uv1{0.0f};
  vec4 color{1.0f};  // COLOR_0 (white without it): multiplies the base colour
};

/// Material values at a surface point after texturing and normal mapping.
struct SurfaceMaterial {
  vec3 albedo{1.0f};
  float opacity = 1.0f;  // base colour alpha (informational; all surfaces are opaque here)
  float metallic = 0.0f;
  float roughness = 1.0f;
  float specular_factor = 1.0f;
  vec3 specular_color{1.0f};
  vec3 emission{0.0f};
  vec3 shading_normal{0.0f, 0.0f, 1.0f};  // unit, after the normal map
};

SurfacePoint interpolate_surface(const Scene& scene, uint32_t triangle, float b1, float b2);
/// Only the triangle, position and geometric normal of interpolate_surface (the same bits): what
/// the path tracer needs of a point sampled on an untextured emitter.
SurfacePoint interpolate_position(const Scene& scene, uint32_t triangle, float b1, float b2);
/// Only the position of interpolate_surface (the same bits).
vec3 interpolated_position(const Scene& scene, uint32_t triangle, float b1, float b2);

/// A material's texture slots, in the order GL binds them (gl/shaders/surface.glsl).
enum TextureSlot : int {
  kSlotBaseColor = 0,
  kSlotMetallicRoughness,
  kSlotNormal,
  kSlotEmissive,
  kTextureSlots
};

/// The lambda (GL 4.5 §8.14, scene/texture_lod.h) each slot's lookup uses. The default, 0, is
/// level 0 with the magnification filter: a lookup without derivatives.
struct SlotLods {
  double lambda[kTextureSlots] = {0.0, 0.0, 0.0, 0.0};
  // sRGB slots (base colour, emissive) decoded after filtering instead of per texel, as GL 4.5
  // §8.24 allows (scene/texture_sample.h); the reference decodes per texel, the slack tries both.
  bool srgb_after_filter = false;
  // Every lookup's sample point moved by this many texels of the level it reads: the 8-bit
  // sub-texel weight precision GL leaves open (scene/texture_sample.h); zero for the reference.
  vec2 texel_shift{0.0f};
  // Added to the filtered normal-map texel (each channel, clamped to [0, 1]): GL returns a lookup
  // of an 8-bit UNORM texture with that format's precision, one step 1/255 (freedoms/lookup_precision.h
  // kUnorm8Step); zero for the reference.
  vec3 normal_texel_offset{0.0f};
  // The filtered sRGB slots (base colour, emissive) moved by this many steps of the 8-bit encoding
  // (re-encoded, shifted, decoded): GL's sRGB decode is precise to half a step (core/precision.h,
  // srgb-decode); zero for the reference.
  float srgb_decode_steps = 0.0f;
};

/// `v` (linear, RGB) moved by `steps` steps of the 8-bit sRGB encoding, clamped to [0, 1].
vec3 shift_srgb_steps(const vec3& v, float steps);

/// A surface sample's lambdas: the reference's own (exact derivatives) and, per slot, every lambda
/// a correct GL may use instead (docs/compare.md, "Texture LOD").
struct SurfaceLods {
  SlotLods exact;
  LodRange range[kTextureSlots];
};

/// The texture and encoding of `slot` in `m`; nullptr when the slot has no texture.
const TextureRef* slot_texture(const Material& m, int slot);
inline bool slot_is_srgb(int slot) {
  return slot == kSlotBaseColor || slot == kSlotEmissive;
}

/// The texture coordinates `ref` reads at `p`: its UV set, through its KHR_texture_transform.
vec2 slot_uv(const TextureRef& ref, const SurfacePoint& p);

/// Evaluates the triangle's material at `p`, each texture looked up at its slot's lambda
/// (scene/texture_sample.h: GL's texel centres, wrap modes, min/mag filters and mip levels);
/// sRGB textures (base colour, emissive) are decoded per texel before filtering, as GL does for
/// SRGB8_ALPHA8.
SurfaceMaterial evaluate_material(const Scene& scene, const SurfacePoint& p,
                                  const SlotLods& lods = {});

/// What evaluate_material reads of its SlotLods, for callers that try many of them (the
/// freedoms): nothing of it where the material has no texture (material_reads_lods false), and
/// srgb_after_filter only where it has an sRGB one (base colour, emissive: GL 4.5 §8.24's decode
/// order does nothing to a linear texture). Where one returns false, every value of what it names
/// gives the same material, bit for bit, so trying one of them is trying them all.
bool material_reads_lods(const Material& m);
bool material_reads_srgb_order(const Material& m);

/// Applies a tangent-space normal map value (already in [-1,1]^3, z reconstructed if needed).
vec3 apply_normal_map(const vec3& normal, const vec4& tangent, vec3 tangent_space_normal, float scale);

}  // namespace vct
