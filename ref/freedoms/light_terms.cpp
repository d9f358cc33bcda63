#include "freedoms/light_terms.h"

#include <algorithm>

#include "stages/light_sample.h"

namespace vct {

LightTerms light_terms(const Scene& scene, const VoxelFragment& f, const SurfaceMaterial& m,
                       const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce) {
  LightTerms t;
  t.rest = m.emission;
  if (bounce && *bounce) t.rest += (*bounce)(f, m);
  t.per_light.assign(scene.lights.size(), vec3(0.0f));
  t.n_dot_l.assign(scene.lights.size(), 0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightSample ls = sample_light(scene.lights[i], settings.light_model, f.position);
    if (ls.irradiance == vec3(0.0f)) continue;
    t.n_dot_l[i] = glm::dot(m.shading_normal, ls.l);
    const float vis = i < maps.size() ? surface_visibility(maps[i], scene.lights[i], f.position, m.shading_normal, settings)
                                      : 1.0f;
    t.per_light[i] = m.albedo * ls.irradiance * (t.n_dot_l[i] * vis * kInvPi);
  }
  return t;
}

float light_change(const LightTerms& a, const LightTerms& b) {
  vec3 front = a.rest - b.rest, behind(0.0f);
  for (size_t i = 0; i < std::min(a.per_light.size(), b.per_light.size()); ++i) {
    const vec3 d = a.per_light[i] - b.per_light[i];
    if (a.n_dot_l[i] > 0.0f && b.n_dot_l[i] > 0.0f)
      front += d;
    else
      behind += glm::abs(d);
  }
  const vec3 bound = glm::abs(front) + behind;
  return std::max(bound.x, std::max(bound.y, bound.z));
}

}  // namespace vct
