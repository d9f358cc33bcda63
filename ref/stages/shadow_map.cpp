#include "stages/shadow_map.h"

#include <algorithm>
#include <cmath>

#include "stages/depth_raster.h"

namespace vct {

mat4 spot_light_view_proj(const SpotLight& light, const Bounds3& scene_bounds) {
  const vec3 dir = glm::normalize(light.direction);
  // The seed's up choice: +z unless nearly parallel (|cos| >= 0.99), then +x.
  vec3 up = std::abs(glm::dot(dir, vec3(0.0f, 0.0f, 1.0f))) < 0.99f ? vec3(0.0f, 0.0f, 1.0f) : vec3(1.0f, 0.0f, 0.0f);
  up = glm::normalize(glm::cross(up, dir));
  const mat4 view = glm::lookAt(light.position, light.position + dir, up);
  float far_plane = 1.0f;
  if (!scene_bounds.empty()) {
    float d = 0.0f;
    for (int c = 0; c < 8; ++c) {
      const vec3 corner((c & 1) ? scene_bounds.hi.x : scene_bounds.lo.x, (c & 2) ? scene_bounds.hi.y : scene_bounds.lo.y,
                        (c & 4) ? scene_bounds.hi.z : scene_bounds.lo.z);
      d = std::max(d, glm::length(corner - light.position));
    }
    far_plane = std::max(d * 1.01f, 1e-3f);
  }
  const float near_plane = far_plane / 20.0f;
  const float fov = std::clamp(2.0f * light.outer_cone_angle, glm::radians(1.0f), glm::radians(170.0f));
  return glm::perspective(fov, 1.0f, near_plane, far_plane) * view;
}

std::vector<ShadowMap> render_shadow_maps(const Scene& scene, const VctSettings& settings) {
  std::vector<ShadowMap> maps;
  const int size = settings.shadow_map_size;
  for (const SpotLight& light : scene.spot_lights) {
    ShadowMap m;
    m.view_proj = spot_light_view_proj(light, scene.bounds);
    m.depth.width = m.depth.height = size;
    m.depth.channels = 1;
    m.depth.channel_names = {"Z"};
    // Alpha-masked texels (foliage) let light through, as GL's depth_only.frag discards them.
    m.depth.data = render_depth(scene.positions, scene.triangles, m.view_proj, size, size, &scene);
    maps.push_back(std::move(m));
  }
  return maps;
}

float shadow_visibility(const ShadowMap& map, const vec3& world_pos, const VctSettings& settings) {
  const vec4 c = map.view_proj * vec4(world_pos, 1.0f);
  if (c.w <= 0.0f) return 1.0f;
  const vec3 ndc = vec3(c) / c.w;
  if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || std::abs(ndc.z) > 1.0f) return 1.0f;
  const float z = ndc.z * 0.5f + 0.5f;
  const int w = map.depth.width, h = map.depth.height;
  // Texel coordinates with y up (GL texture space); the image stores row 0 = top.
  const float u = (ndc.x * 0.5f + 0.5f) * float(w), v = (ndc.y * 0.5f + 0.5f) * float(h);
  const int k = std::max(1, settings.pcf_kernel);
  const float half = 0.5f * float(k - 1);
  int lit = 0;
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const int tx = std::clamp(int(std::floor(u + float(i) - half)), 0, w - 1);
      const int ty = std::clamp(int(std::floor(v + float(j) - half)), 0, h - 1);
      if (z <= map.depth.at(tx, h - 1 - ty, 0) + settings.shadow_bias) ++lit;
    }
  }
  return float(lit) / float(k * k);
}

}  // namespace vct
