#include "stages/soft_shadow.h"

#include <cmath>

#include "core/parallel.h"
#include "shared/vct_shared.h"
#include "stages/cone_sets.h"

namespace vct {

vec3 spot_light_radiance(const SpotLight& light, const VctSettings& s, const vec3& p, const vec3& n, const vec3& v,
                         const SurfaceMaterial& m) {
  vec3 l = light.position - p;
  const float dist = glm::length(l);
  if (dist <= 0.0f) return vec3(0.0f);
  l /= dist;
  const float n_dot_l = glm::dot(n, l);
  if (n_dot_l <= 0.0f) return vec3(0.0f);
  const int model = s.light_model == LightModel::Seed ? sh::LIGHT_MODEL_SEED : sh::LIGHT_MODEL_GLTF;
  const vec3 e = sh::spot_irradiance(model, light.color, light.intensity, dist, glm::dot(-l, glm::normalize(light.direction)),
                                     std::cos(light.inner_cone_angle), std::cos(light.outer_cone_angle), light.range);
  const sh::SurfacePbr pbr = sh::surface_pbr(m.albedo, m.metallic, m.roughness, m.specular_factor, m.specular_color);
  return sh::cook_torrance(pbr, n, v, l) * e * n_dot_l;
}

SurfaceMaterial gbuffer_material(const GBuffer& g, int x, int y) {
  SurfaceMaterial m;
  m.albedo = g.albedo.rgb(x, y);
  m.metallic = g.material.at(x, y, 0);
  m.roughness = g.material.at(x, y, 1);
  m.specular_factor = g.material.at(x, y, 2);
  m.specular_color = g.specular_color.rgb(x, y);
  m.emission = g.emission.rgb(x, y);
  m.shading_normal = g.normal.rgb(x, y);
  return m;
}

Image shade_direct_soft(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const VctSettings& s,
                        Image* visibility) {
  const int w = g.coverage.width, h = g.coverage.height;
  Image out(w, h, 3);
  out.channel_names = {"R", "G", "B"};
  if (visibility) {
    *visibility = Image(w, h, 1, 1.0f);
    visibility->channel_names = {"Y"};
  }
  const ConeFrame cones(mips, scene.volume, s);  // once per frame: the per-pixel loop only traces
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      const vec3 p = g.position.rgb(x, y);
      const SurfaceMaterial m = gbuffer_material(g, x, y);
      const vec3 v = scene.camera.to_eye(p);
      vec3 sum(0.0f);
      float vis_sum = 0.0f;
      for (const SpotLight& light : scene.spot_lights) {
        const float vis = cones.shadow(p, light.position);
        vis_sum += vis;
        sum += vis * spot_light_radiance(light, s, p, m.shading_normal, v, m);
      }
      out.set_rgb(x, y, sum);
      if (visibility && !scene.spot_lights.empty()) visibility->at(x, y, 0) = vis_sum / float(scene.spot_lights.size());
    }
  });
  return out;
}

}  // namespace vct
