#include "stages/direct.h"

#include <cmath>

#include "core/parallel.h"
#include "shared/vct_shared.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

int shared_light_model(LightModel m) { return m == LightModel::Seed ? sh::LIGHT_MODEL_SEED : sh::LIGHT_MODEL_GLTF; }

// Irradiance at p on a surface facing the light (before n.l), and the unit direction to the light.
vec3 light_irradiance(const SpotLight& light, const VctSettings& s, const vec3& p, vec3& l) {
  const vec3 to_light = light.position - p;
  const float dist = glm::length(to_light);
  l = dist > 0.0f ? to_light / dist : vec3(0.0f, 0.0f, 1.0f);
  const float cos_axis = glm::dot(-l, glm::normalize(light.direction));
  return sh::spot_irradiance(shared_light_model(s.light_model), light.color, light.intensity, dist, cos_axis,
                             std::cos(light.inner_cone_angle), std::cos(light.outer_cone_angle), light.range);
}

float visibility(const std::vector<ShadowMap>& maps, size_t i, const VctSettings& s, const vec3& p) {
  return i < maps.size() ? shadow_visibility(maps[i], p, s) : 1.0f;
}

}  // namespace

vec3 direct_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings, const vec3& p,
                     const vec3& n, const vec3& view_dir, const SurfaceMaterial& m) {
  const sh::SurfacePbr pbr = sh::surface_pbr(m.albedo, m.metallic, m.roughness, m.specular_factor, m.specular_color);
  vec3 sum(0.0f);
  for (size_t i = 0; i < scene.spot_lights.size(); ++i) {
    vec3 l;
    const vec3 e = light_irradiance(scene.spot_lights[i], settings, p, l);
    const float n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0f || e == vec3(0.0f)) continue;
    sum += sh::cook_torrance(pbr, n, view_dir, l) * e * n_dot_l * visibility(maps, i, settings, p);
  }
  return sum;
}

vec3 diffuse_outgoing_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings,
                               const vec3& p, const vec3& n, const vec3& albedo) {
  vec3 irradiance(0.0f);
  for (size_t i = 0; i < scene.spot_lights.size(); ++i) {
    vec3 l;
    const vec3 e = light_irradiance(scene.spot_lights[i], settings, p, l);
    const float n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0f || e == vec3(0.0f)) continue;
    irradiance += e * n_dot_l * visibility(maps, i, settings, p);
  }
  return albedo * irradiance * kInvPi;
}

Image shade_direct(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps,
                   const VctSettings& settings) {
  Image out(g.position.width, g.position.height, 3);
  out.channel_names = {"R", "G", "B"};
  parallel_rows(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      SurfaceMaterial m;
      const vec3 p = g.position.rgb(x, y);
      m.albedo = g.albedo.rgb(x, y);
      m.metallic = g.material.at(x, y, 0);
      m.roughness = g.material.at(x, y, 1);
      m.specular_factor = g.material.at(x, y, 2);
      m.specular_color = g.specular_color.rgb(x, y);
      m.shading_normal = g.normal.rgb(x, y);
      const vec3 v = scene.camera.to_eye(p);
      out.set_rgb(x, y, direct_radiance(scene, maps, settings, p, m.shading_normal, v, m));
    }
  });
  return out;
}

}  // namespace vct
