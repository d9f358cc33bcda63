#include "stages/soft_shadow.h"

#include <cmath>

#include "core/parallel.h"
#include "shared/vct_shared.h"
#include "stages/cone_sets.h"
#include "stages/light_sample.h"

namespace vct {

vec3 light_radiance(const Light& light, const VctSettings& s, const vec3& p, const vec3& n, const vec3& v,
                    const SurfaceMaterial& m) {
  const LightSample ls = sample_light(light, s.light_model, p);
  if (!(ls.distance > 0.0f)) return vec3(0.0f);
  const float n_dot_l = glm::dot(n, ls.l);
  if (n_dot_l <= 0.0f) return vec3(0.0f);
  const sh::SurfacePbr pbr = sh::surface_pbr(m.albedo, m.metallic, m.roughness, m.specular_factor, m.specular_color);
  return sh::cook_torrance_nv(pbr, n, v, ls.l, nv_mode(s.n_dot_v)) * ls.irradiance * n_dot_l;
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
      for (const Light& light : scene.lights) {
        const float vis = cones.shadow(p, light);
        vis_sum += vis;
        sum += vis * light_radiance(light, s, p, m.shading_normal, v, m);
      }
      out.set_rgb(x, y, sum);
      if (visibility && !scene.lights.empty()) visibility->at(x, y, 0) = vis_sum / float(scene.lights.size());
    }
  });
  return out;
}

}  // namespace vct
