#include "stages/direct.h"

#include <cmath>

#include "core/parallel.h"
#include "shared/vct_shared.h"
#include "stages/gbuffer.h"
#include "stages/light_sample.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

// The PCF visibility at the surface point's normal-offset lookup point (stages/shadow_map.h).
float visibility(const Scene& scene, const std::vector<ShadowMap>& maps, size_t i, const VctSettings& s, const vec3& p,
                 const vec3& n) {
  return i < maps.size() ? surface_visibility(maps[i], scene.lights[i], p, n, s) : 1.0f;
}

}  // namespace

vec3 unshadowed_light(const Scene& scene, size_t i, const VctSettings& settings, const vec3& p, const vec3& n,
                      const vec3& view_dir, const sh::SurfacePbr& pbr) {
  const LightSample ls = sample_light(scene.lights[i], settings.light_model, p);
  const vec3 l = ls.l, e = ls.irradiance;
  const float n_dot_l = glm::dot(n, l);
  if (n_dot_l <= 0.0f || e == vec3(0.0f)) return vec3(0.0f);
  return sh::cook_torrance_nv(pbr, n, view_dir, l, nv_mode(settings.n_dot_v)) * e * n_dot_l;
}

sh::SurfacePbr surface_of(const SurfaceMaterial& m) {
  return sh::surface_pbr(m.albedo, m.metallic, m.roughness, m.specular_factor, m.specular_color);
}

vec3 direct_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings, const vec3& p,
                     const vec3& n, const vec3& view_dir, const SurfaceMaterial& m) {
  const sh::SurfacePbr pbr = surface_of(m);
  vec3 sum(0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const vec3 c = unshadowed_light(scene, i, settings, p, n, view_dir, pbr);
    // ((brdf * E) * n.l) * visibility, the product's order as before (and as direct.frag).
    if (c != vec3(0.0f)) sum += c * visibility(scene, maps, i, settings, p, n);
  }
  return sum;
}

vec3 diffuse_outgoing_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings,
                               const vec3& p, const vec3& n, const vec3& albedo) {
  vec3 irradiance(0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightSample ls = sample_light(scene.lights[i], settings.light_model, p);
    const vec3 l = ls.l, e = ls.irradiance;
    const float n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0f || e == vec3(0.0f)) continue;
    irradiance += e * n_dot_l * visibility(scene, maps, i, settings, p, n);
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
      const SurfaceMaterial m = gbuffer_material(g, x, y);
      const vec3 p = g.position.rgb(x, y);
      const vec3 v = scene.camera.to_eye(p);
      out.set_rgb(x, y, direct_radiance(scene, maps, settings, p, m.shading_normal, v, m));
    }
  });
  return out;
}

}  // namespace vct
