#include "stages/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "core/error.h"
#include "core/light_matrices.h"
#include "core/pcf_taps.h"
#include "stages/cube_map.h"
#include "stages/depth_raster.h"

namespace vct {

namespace {

// The seed's up choice: +z unless nearly parallel to the light's direction (|cos| >= 0.99), then +x.
vec3 light_up(const vec3& dir) {
  const vec3 up = std::abs(glm::dot(dir, vec3(0.0f, 0.0f, 1.0f))) < 0.99f ? vec3(0.0f, 0.0f, 1.0f) : vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(glm::cross(up, dir));
}

vec3 box_corner(const vec3& lo, const vec3& hi, int c) {
  return vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
}

Image depth_image(int size, std::vector<float> data, ShadowDepthFormat format) {
  for (float& z : data) z = stored_window_depth(z, format);
  Image img;
  img.width = img.height = size;
  img.channels = 1;
  img.channel_names = {"Z"};
  img.data = std::move(data);
  return img;
}


// One tap at texel position `t` (continuous, y up): `lit(ix, iy)` of the texel it falls in
// (nearest), or GL's LINEAR on a shadow sampler -- the four texels around t - 0.5 weighted
// bilinearly, each compared on its own (GL 4.5 section 8.23.1; equations 8.9-8.11 for i0, alpha).
template <typename LitTexel>
float tap_visibility(const vec2& t, ShadowCompare compare, const LitTexel& lit) {
  if (compare == ShadowCompare::Nearest) return lit(int(std::floor(t.x)), int(std::floor(t.y))) ? 1.0f : 0.0f;
  const vec2 s = t - 0.5f;
  const vec2 i0 = glm::floor(s);
  const vec2 a = s - i0;
  const int x = int(i0.x), y = int(i0.y);
  return (1.0f - a.x) * (1.0f - a.y) * float(lit(x, y)) + a.x * (1.0f - a.y) * float(lit(x + 1, y)) +
         (1.0f - a.x) * a.y * float(lit(x, y + 1)) + a.x * a.y * float(lit(x + 1, y + 1));
}

// One tap of an engine that filters first (filters_depth_first): GL LINEAR on a plain sampler2D
// blends the four stored depths around t - 0.5 (GL 4.5 section 8.14.2, equation 8.10's weights),
// and the point's window depth z is compared once with that blend (the source design's
// textureProj then `pointDepth - bias >= shadowDepth`). `stored(ix, iy)`: the texel's depth.
template <typename StoredTexel>
float filtered_tap_visibility(const vec2& t, float z, float bias, const StoredTexel& stored) {
  const vec2 s = t - 0.5f;
  const vec2 i0 = glm::floor(s);
  const vec2 a = s - i0;
  const int x = int(i0.x), y = int(i0.y);
  const float d = (1.0f - a.x) * (1.0f - a.y) * stored(x, y) + a.x * (1.0f - a.y) * stored(x + 1, y) +
                  (1.0f - a.x) * a.y * stored(x, y + 1) + a.x * a.y * stored(x + 1, y + 1);
  return z <= d + bias ? 1.0f : 0.0f;
}

// PCF over one 2D depth image: the taps and the test of shadow_visibility (header). `clip_w`: the
// point's light-clip w (taps declared with pcf_tap_scale = inv_w shrink with it).
float pcf_2d(const Image& depth, const vec3& ndc, float clip_w, const VctSettings& settings) {
  const float z = ndc.z * 0.5f + 0.5f;
  const int w = depth.width, h = depth.height;
  // Texel coordinates with y up (GL texture space); the image stores row 0 = top.
  const float u = (ndc.x * 0.5f + 0.5f) * float(w), v = (ndc.y * 0.5f + 0.5f) * float(h);
  const auto stored = [&](int tx, int ty) { return stored_depth(depth, tx, ty, settings.shadow_border); };
  const auto lit = [&](int tx, int ty) { return z <= stored(tx, ty) + settings.shadow_bias; };
  const bool filter_first = filters_depth_first(settings);
  float sum = 0.0f;
  const int taps = for_each_tap(u, v, settings, w, clip_w, [&](const vec2& t) {
    sum += filter_first ? filtered_tap_visibility(t, z, settings.shadow_bias, stored)
                        : tap_visibility(t, settings.shadow_compare, lit);
  });
  return sum / float(taps);
}

}  // namespace

// The tap positions of a lookup at texel coordinate (u, v): the pcf_kernel square at
// u + i - (k-1)/2 (the arithmetic GL's lights.glsl repeats, so default taps floor identically),
// or the engine's offsets (core/pcf_taps.h) in its unit and scale.
std::vector<vec2> tap_positions(float u, float v, const VctSettings& settings, int size, float clip_w) {
  std::vector<vec2> out;
  for_each_tap(u, v, settings, size, clip_w, [&](const vec2& t) { out.push_back(t); });
  return out;
}

const std::vector<vec2>& parsed_pcf_taps(const VctSettings& settings) {
  thread_local std::string parsed_text;
  thread_local std::vector<vec2> offsets;
  if (parsed_text != settings.pcf_taps) {
    offsets = parse_pcf_taps(settings.pcf_taps);
    parsed_text = settings.pcf_taps;
  }
  return offsets;
}

double depth_quantum(ShadowDepthFormat format) {
  switch (format) {
    case ShadowDepthFormat::Depth24: return 1.0 / double((1u << 24) - 1u);
    case ShadowDepthFormat::Depth16: return 1.0 / double((1u << 16) - 1u);
    case ShadowDepthFormat::Depth32f: break;
  }
  return 0.0;
}

float stored_window_depth(float z, ShadowDepthFormat format) {
  const double q = depth_quantum(format);
  if (q == 0.0) return z;
  // In double: 2^24 - 1 steps do not fit a float's mantissa exactly at the rounding.
  const double steps = std::nearbyint(std::clamp(double(z), 0.0, 1.0) / q);
  return float(steps * q);
}

mat4 spot_light_view_proj(const Light& light, const Bounds3& scene_bounds) {
  return spot_light_view_proj(light, scene_bounds, VctSettings{});
}

mat4 spot_light_view_proj(const Light& light, const Bounds3& scene_bounds, const VctSettings& settings) {
  const vec3 dir = glm::normalize(light.direction);
  const mat4 view = glm::lookAt(light.position, light.position + dir, light_up(dir));
  vec2 range = light_depth_range(light, scene_bounds);  // near = far / 20
  if (settings.shadow_far > 0.0f) range.y = settings.shadow_far;
  if (settings.shadow_near > 0.0f) range.x = settings.shadow_near;
  const float fov = settings.shadow_fov_deg > 0.0f
                        ? glm::radians(settings.shadow_fov_deg)
                        : std::clamp(2.0f * light.outer_cone_angle, glm::radians(1.0f), glm::radians(170.0f));
  return glm::perspective(fov, 1.0f, range.x, range.y) * view;
}


mat4 directional_light_view(const Light& light, const VoxelVolume& volume) {
  const vec3 dir = glm::normalize(light.direction);
  const vec3 center = volume.to_world(vec3(0.5f));
  // From one edge length behind the centre: outside the cube (its half diagonal is 0.87 of it).
  return glm::lookAt(center - dir * volume.size, center, light_up(dir));
}

mat4 directional_light_view_proj(const Light& light, const VoxelVolume& volume) {
  const mat4 view = directional_light_view(light, volume);
  vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int c = 0; c < 8; ++c) {
    const vec3 v = vec3(view * vec4(box_corner(volume.origin, volume.origin + vec3(volume.size), c), 1.0f));
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  // View space looks down -z: near = -(largest z), far = -(smallest z).
  return glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z) * view;
}

vec2 light_depth_range(const Light& light, const Bounds3& scene_bounds) {
  float far_plane = 1.0f;
  if (!scene_bounds.empty()) {
    float d = 0.0f;
    for (int c = 0; c < 8; ++c) d = std::max(d, glm::length(box_corner(scene_bounds.lo, scene_bounds.hi, c) - light.position));
    far_plane = std::max(d * 1.01f, 1e-3f);
  }
  return vec2(far_plane / 20.0f, far_plane);
}

mat4 light_view_proj(const Scene& scene, size_t index, const VctSettings& settings) {
  const Light& light = scene.lights[index];
  const std::map<int, mat4> matrices = parse_light_matrices(settings.shadow_view_proj);
  const std::map<int, std::array<float, 6>> boxes = parse_ortho_boxes(settings.shadow_ortho_box);
  const auto matrix = matrices.find(int(index));
  const auto box = boxes.find(int(index));
  if (matrix != matrices.end() && box != boxes.end())
    throw InputError("settings", "light " + std::to_string(index) + " has both a shadow_view_proj and a shadow_ortho_box");
  if (matrix != matrices.end()) return matrix->second;
  if (box != boxes.end()) {
    if (!light.is_directional())
      throw InputError("settings", "shadow_ortho_box: light " + std::to_string(index) + " is not a directional light");
    const std::array<float, 6>& b = box->second;
    return glm::ortho(b[0], b[1], b[2], b[3], b[4], b[5]) * directional_light_view(light, scene.volume);
  }
  return light.is_directional() ? directional_light_view_proj(light, scene.volume)
                                : spot_light_view_proj(light, scene.bounds, settings);
}

namespace {
// Every light a matrix or box names must exist and have a 2D map (a point light's cube keeps GL's
// six faces, cube_map.h).
void check_declared_lights(const Scene& scene, const VctSettings& settings) {
  // A cube's lookup compares each texel in the face it lies on (cube_shadow_visibility): one
  // filtered depth over texels of two faces has no single depth to compare with.
  if (filters_depth_first(settings))
    for (const Light& light : scene.lights)
      if (light.is_point())
        throw InputError("settings", "shadow_filter_order = filter_then_compare is for spot and directional lights' 2D "
                                     "maps; the scene has a point light (its cube compares per face)");
  std::vector<int> named;
  for (const auto& [i, m] : parse_light_matrices(settings.shadow_view_proj)) named.push_back(i);
  for (const auto& [i, b] : parse_ortho_boxes(settings.shadow_ortho_box)) named.push_back(i);
  for (int i : named) {
    if (size_t(i) >= scene.lights.size())
      throw InputError("settings", "shadow_view_proj/shadow_ortho_box: light " + std::to_string(i) +
                                       " does not exist (the scene has " + std::to_string(scene.lights.size()) + ")");
    if (scene.lights[size_t(i)].is_point())
      throw InputError("settings", "shadow_view_proj: light " + std::to_string(i) +
                                       " is a point light (its cube faces are fixed by GL 4.5 section 8.13)");
  }
}
}  // namespace

std::vector<ShadowMap> render_shadow_maps(const Scene& scene, const VctSettings& settings) {
  check_declared_lights(scene, settings);
  std::vector<ShadowMap> maps;
  const int size = settings.shadow_map_size;
  for (size_t index = 0; index < scene.lights.size(); ++index) {
    const Light& light = scene.lights[index];
    ShadowMap m;
    if (light.is_point()) {
      const vec2 range = light_depth_range(light, scene.bounds);
      for (int f = 0; f < 6; ++f) {
        m.cube_view_proj[size_t(f)] = cube_face_view_proj(f, light.position, range.x, range.y);
        m.cube[size_t(f)] =
            depth_image(size, render_depth(scene.positions, scene.triangles, m.cube_view_proj[size_t(f)], size, size, &scene),
                        settings.shadow_depth_format);
      }
    } else {
      m.view_proj = light_view_proj(scene, index, settings);
      // Alpha-masked texels (foliage) let light through, as GL's depth_only.frag discards them.
      m.depth =
          depth_image(size, render_depth(scene.positions, scene.triangles, m.view_proj, size, size, &scene),
                      settings.shadow_depth_format);
    }
    maps.push_back(std::move(m));
  }
  return maps;
}

int shadow_map_layers(const Scene& scene) {
  int layers = 0;
  for (const Light& light : scene.lights) layers += light.is_point() ? 6 : 1;
  return layers;
}

float shadow_visibility(const ShadowMap& map, const vec3& world_pos, const VctSettings& settings) {
  const vec4 c = map.view_proj * vec4(world_pos, 1.0f);
  if (c.w <= 0.0f) return 1.0f;
  const vec3 ndc = vec3(c) / c.w;
  if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || std::abs(ndc.z) > 1.0f) return 1.0f;
  return pcf_2d(map.depth, ndc, c.w, settings);
}

float cube_shadow_visibility(const ShadowMap& map, const vec3& light_position, const vec3& world_pos,
                             const VctSettings& settings) {
  const vec3 r = world_pos - light_position;
  if (r == vec3(0.0f)) return 1.0f;
  const int size = map.cube[0].width;
  const int home = cube_face(r);
  const vec2 st = cube_face_st(home, r);
  const auto lit = [&](int tx, int ty) {
    const CubeTexel texel = cube_texel(home, tx, ty, size);  // past the edge: the face GL reads
    const int face = texel.face;
    tx = texel.x, ty = texel.y;
    // The point's depth in the face this texel is on; outside that face's depth range it is lit.
    const vec4 c = map.cube_view_proj[size_t(face)] * vec4(world_pos, 1.0f);
    const float z = c.z / c.w * 0.5f + 0.5f;
    if (!(c.w > 0.0f) || z < 0.0f || z > 1.0f) return true;
    return z <= map.cube[size_t(face)].at(tx, size - 1 - ty, 0) + settings.shadow_bias;
  };
  // The home face's clip w (its distance along the face's axis) scales taps declared per 1/w.
  const float clip_w = (map.cube_view_proj[size_t(home)] * vec4(world_pos, 1.0f)).w;
  float sum = 0.0f;
  const int taps = for_each_tap(st.x * float(size), st.y * float(size), settings, size, clip_w,
                                [&](const vec2& t) { sum += tap_visibility(t, settings.shadow_compare, lit); });
  return sum / float(taps);
}

vec2 pcf_reach(const VctSettings& settings) {
  vec2 reach(0.0f);
  // At w = 1: with pcf_tap_scale = inv_w the normal offset is off (validate_settings).
  for_each_tap(0.0f, 0.0f, settings, settings.shadow_map_size, 1.0f,
               [&](const vec2& t) { reach = glm::max(reach, glm::abs(t)); });
  return reach + (settings.shadow_compare == ShadowCompare::Nearest ? 0.5f : 1.0f);
}

const mat4* offset_matrix(const ShadowMap& map, const Light& light, const vec3& p) {
  if (light.is_point()) {
    const vec3 r = p - light.position;
    return map.is_cube() && r != vec3(0.0f) ? &map.cube_view_proj[size_t(cube_face(r))] : nullptr;
  }
  return map.depth.empty() ? nullptr : &map.view_proj;
}

float normal_offset_per_w(const mat4& m, const vec3& n, const VctSettings& settings) {
  const vec3 r0(m[0][0], m[1][0], m[2][0]), r1(m[0][1], m[1][1], m[2][1]);
  const vec2 reach = pcf_reach(settings);
  const float per_texel = 2.0f / float(settings.shadow_map_size);
  return settings.shadow_normal_offset * per_texel *
         (reach.x * std::abs(glm::dot(n, r0)) / glm::dot(r0, r0) + reach.y * std::abs(glm::dot(n, r1)) / glm::dot(r1, r1));
}

vec3 shadow_lookup_point(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                         const VctSettings& settings) {
  if (settings.shadow_normal_offset == 0.0f) return p;
  const mat4* m = offset_matrix(map, light, p);
  if (!m) return p;
  const float w = ((*m) * vec4(p, 1.0f)).w;
  if (!(w > 0.0f)) return p;
  return p + (normal_offset_per_w(*m, n, settings) * w) * n;
}

float surface_visibility(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                         const VctSettings& settings) {
  return light_visibility(map, light, shadow_lookup_point(map, light, p, n, settings), settings);
}

float light_visibility(const ShadowMap& map, const Light& light, const vec3& world_pos, const VctSettings& settings) {
  if (light.is_point()) return map.is_cube() ? cube_shadow_visibility(map, light.position, world_pos, settings) : 1.0f;
  return map.depth.empty() ? 1.0f : shadow_visibility(map, world_pos, settings);
}

}  // namespace vct
