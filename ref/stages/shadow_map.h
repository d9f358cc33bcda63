// Shadow maps of the three light kinds: depth rendered from each light with the depth-only path of
// the software rasterizer (stages/depth_raster.h) -- a perspective map per spot, an orthographic
// map fitted to the voxel volume per directional light, a cube of six 90 degree faces per point
// light -- and the PCF lookup used by direct lighting and light injection (docs/pipeline.md,
// "Shadow maps").
#pragma once

#include <algorithm>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// World -> light clip space for one spot: glm::lookAt from the light along its direction with a
/// robust up vector (+z unless the direction is within ~8 degrees of it, then +x: the seed's
/// rule), and a square perspective whose full field of view is twice the outer cone angle
/// (clamped to [1, 170] degrees). far = distance to the farthest corner of `scene_bounds` (x1.01),
/// near = far / 20 (keeps the constant NDC depth bias meaningful; see docs).
mat4 spot_light_view_proj(const Light& light, const Bounds3& scene_bounds);
/// The same with an engine's frustum where the settings give one (shadow_fov_deg, shadow_near,
/// shadow_far; 0 keeps the rule above for that parameter). Both backends call this.
mat4 spot_light_view_proj(const Light& light, const Bounds3& scene_bounds, const VctSettings& settings);

/// World -> light clip space for a directional light: the view looks along the light's direction
/// (the spot's up rule) from outside the voxel volume, and an orthographic box is fitted to the
/// volume's 8 corners projected into that view (x, y and depth), so every point of the volume is
/// inside the map and depth spans exactly the volume along the light.
mat4 directional_light_view_proj(const Light& light, const VoxelVolume& volume);

/// The view of directional_light_view_proj alone (an engine's shadow_ortho_box is given in it).
mat4 directional_light_view(const Light& light, const VoxelVolume& volume);

/// World -> light clip space of scene light `index` (spot or directional) as the settings make it:
/// the engine's shadow_view_proj or shadow_ortho_box (core/light_matrices.h) where one names the
/// light, else the rules above. Throws InputError for a box on a light that is not directional or
/// a light given both.
mat4 light_view_proj(const Scene& scene, size_t index, const VctSettings& settings);

/// Near and far planes of a spot light and of a point light's cube faces (far = distance to the
/// farthest corner of `scene_bounds` x1.01, near = far / 20).
vec2 light_depth_range(const Light& light, const Bounds3& scene_bounds);

/// Window depth z as a map of `format` stores it: unchanged for depth32f; for b-bit UNORM
/// (depth24, depth16) clamped to [0, 1] and rounded to the nearest multiple of 1 / (2^b - 1)
/// (GL 4.5 section 2.3.5.2 lets an implementation take either neighbour, preferring the nearest).
float stored_window_depth(float z, ShadowDepthFormat format);

/// One step of `format`'s stored depth: 1 / (2^b - 1), 0 for float.
double depth_quantum(ShadowDepthFormat format);

/// One entry per light, in the scene's order (settings.shadow_map_size squared per map or face,
/// GL_LESS, cleared to 1, stored as settings.shadow_depth_format): `depth` for spot and directional
/// lights, six `cube` faces for point lights.
std::vector<ShadowMap> render_shadow_maps(const Scene& scene, const VctSettings& settings);

/// How many square depth images the scene's lights need (one per spot or directional light, six
/// per point light): what the memory estimate and the GL texture array count.
int shadow_map_layers(const Scene& scene);

/// The PCF tap positions of a lookup at texel coordinate (u, v) of a map `size` texels wide: the
/// pcf_kernel square at u + i - (k-1)/2 (the arithmetic GL's lights.glsl repeats), or the
/// engine's pcf_taps offsets -- in texels, or (pcf_tap_unit = uv) texture coordinates times
/// `size`, and (pcf_tap_scale = inv_w) divided by the point's light-clip w `clip_w`.
std::vector<vec2> tap_positions(float u, float v, const VctSettings& settings, int size, float clip_w);

/// The engine's pcf_taps offsets parsed (core/pcf_taps.h), once per thread and tap text: a lookup
/// runs per fragment and per pixel.
const std::vector<vec2>& parsed_pcf_taps(const VctSettings& settings);

/// Calls tap(t) for each of tap_positions(u, v, settings, size, clip_w) in its order and with its
/// arithmetic, without building the vector (the lookups' hot loop); returns how many.
template <typename Tap>
int for_each_tap(float u, float v, const VctSettings& settings, int size, float clip_w, Tap&& tap) {
  if (settings.pcf_taps.empty()) {
    const int k = std::max(1, settings.pcf_kernel);
    const float half = 0.5f * float(k - 1);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) tap(vec2(u + float(i) - half, v + float(j) - half));
    return k * k;
  }
  const std::vector<vec2>& offsets = parsed_pcf_taps(settings);
  const bool uv = settings.pcf_tap_unit == PcfTapUnit::Uv;
  const bool inv_w = settings.pcf_tap_scale == PcfTapScale::InvW;
  for (const vec2& o : offsets) {
    vec2 t = uv ? o * float(size) : o;  // UV offsets: texture coordinates times the map's size
    if (inv_w) t /= clip_w;            // added to clip xy before the divide: o / w after it
    tap(vec2(u + t.x, v + t.y));
  }
  return int(offsets.size());
}

/// The depth texel (tx, ty) (y up, may lie past the edge) of a 2D map holds: the edge texel's
/// (shadow_border = clamp, GL CLAMP_TO_EDGE), or past the edge 1 (lit) or 0 (shadowed), GL
/// CLAMP_TO_BORDER's border colour.
/// (Inline: every PCF tap and every texel of the freedoms' range searches reads it.)
inline float stored_depth(const Image& depth, int tx, int ty, ShadowBorder border) {
  const int w = depth.width, h = depth.height;
  const bool inside = tx >= 0 && ty >= 0 && tx < w && ty < h;
  // CLAMP_TO_BORDER: the border colour's R is the depth a texel past the edge holds (GL 4.5
  // sections 8.14.2, 8.23.1).
  if (!inside && border != ShadowBorder::Clamp) return border == ShadowBorder::Lit ? 1.0f : 0.0f;
  // Clamp to edge: a texel past the border reads the border texel.
  return depth.at(std::clamp(tx, 0, w - 1), h - 1 - std::clamp(ty, 0, h - 1), 0);
}

/// PCF visibility in [0,1] (1 = lit) of a world point for one light: the mean over the taps --
/// settings.pcf_kernel^2 at texel offsets (i - (k-1)/2), or the engine's settings.pcf_taps
/// (core/pcf_taps.h, tap_positions) -- of each tap's compare: its texel (shadow_compare nearest)
/// or GL LINEAR's bilinear weighting of the four texels around it (linear), each compared
/// (compare_then_filter) or their depths blended and compared once (filter_then_compare);
/// texels past the edge as shadow_border says (stored_depth); a texel is lit when the point's
/// window depth <= stored depth + settings.shadow_bias. Points outside the light's frustum are lit
/// (the spot falloff is zero there anyway). Cube maps: cube_shadow_visibility.
float shadow_visibility(const ShadowMap& map, const vec3& world_pos, const VctSettings& settings);

/// A point light's PCF over its cube: the taps (as above) around the point on the face its
/// direction selects (cube_map.h), each compared as above; a texel past that face's edge takes
/// the direction through its (virtual) centre and reads the texel that direction selects on the
/// neighbouring face, comparing the point's window depth in that face (+ settings.shadow_bias).
/// With linear compare this stands in for GL's seamless cube filtering (at a cube corner GL may
/// blend differently: not judged against GL, which does not run the engine's PCF).
float cube_shadow_visibility(const ShadowMap& map, const vec3& light_position, const vec3& world_pos,
                             const VctSettings& settings);

/// The visibility of `light` at a world point through its map: the cube's for a point light,
/// else the 2D map's.
float light_visibility(const ShadowMap& map, const Light& light, const vec3& world_pos, const VctSettings& settings);

/// Normal-offset bias (docs/pipeline.md, "Normal offset"). How far, in texels, the PCF footprint
/// reaches from the lookup coordinate along each axis: the largest |tap offset| + 1/2 (nearest
/// reads the texel the tap falls in) or + 1 (linear blends the four around it). 3x3 nearest: 1.5.
vec2 pcf_reach(const VctSettings& settings);

/// The matrix whose texels the normal offset of a surface point at `p` is measured in: the 2D
/// map's, or the cube face the direction p - light selects (nullptr: the light has no map).
const mat4* offset_matrix(const ShadowMap& map, const Light& light, const vec3& p);

/// The normal offset per unit of clip w through world -> clip matrix m for unit normal n:
/// K = shadow_normal_offset x (2 / S) x (R.x |n.r0| / |r0|^2 + R.y |n.r1| / |r1|^2), r0 and r1 the
/// xyz of the matrix's rows 0 and 1, R = pcf_reach, S = shadow_map_size. The lookup point is
/// p + K w n: for a plane through p with normal n, every texel the footprint reads then stores
/// a depth at or behind the lookup point's (docs/pipeline.md derives it); GL's lights.glsl
/// repeats this arithmetic.
float normal_offset_per_w(const mat4& m, const vec3& n, const VctSettings& settings);

/// Where a surface point p with unit normal n (facing the camera) is looked up in `light`'s map:
/// p + K w n (above) with w = the clip w of p through offset_matrix; p itself when the matrix is
/// missing, w <= 0 or the offset is 0.
vec3 shadow_lookup_point(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                         const VctSettings& settings);

/// light_visibility at the surface point's lookup point: what direct light and light injection
/// use (ref and GL alike).
float surface_visibility(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                         const VctSettings& settings);

}  // namespace vct
