#include "freedoms/direct_ties.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "freedoms/gbuffer_ties.h"
#include "freedoms/shadow_ties.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/light_sample.h"

namespace vct {

namespace {

constexpr const char* kGroups[2] = {"image.direct", "image.emission"};

// The light's term with its hard-spot step taken as lit, when p is within the tie band of the
// edge; zero otherwise (no alternative).
vec3 hard_spot_lit_alternative(const Light& light, const VctSettings& s, const vec3& p, const vec3& n, const vec3& v,
                               const sh::SurfacePbr& pbr) {
  const LightSample ls = hard_spot_lit_sample(light, s.light_model, p);
  if (ls.irradiance == vec3(0.0f)) return vec3(0.0f);
  const float n_dot_l = glm::dot(n, ls.l);
  if (n_dot_l <= 0.0f) return vec3(0.0f);
  // The view cosine as the direct light takes it (setting n_dot_v, stages/direct.cpp).
  return sh::cook_torrance_nv(pbr, n, v, ls.l, nv_mode(s.n_dot_v)) * ls.irradiance * n_dot_l;
}

// [lo, hi] of the direct light at a covered pixel: each light's unshadowed term times the ends
// of its admissible visibility (and, at a hard spot's edge, dark or lit).
void direct_range_at(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps, const VctSettings& s,
                     int x, int y, vec3& lo, vec3& hi) {
  const SurfaceMaterial m = gbuffer_material(g, x, y);
  const sh::SurfacePbr pbr = surface_of(m);
  const vec3 p = g.position.rgb(x, y);
  const vec3 v = scene.camera.to_eye(p);
  lo = hi = vec3(0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const vec3 c = unshadowed_light(scene, i, s, p, m.shading_normal, v, pbr);
    const vec3 edge = hard_spot_lit_alternative(scene.lights[i], s, p, m.shading_normal, v, pbr);
    if (c == vec3(0.0f) && edge == vec3(0.0f)) continue;
    const VisibilityRange r =
        i < maps.size() ? surface_visibility_range(maps[i], scene.lights[i], p, m.shading_normal, s)
                        : VisibilityRange{};
    const bool tie = edge != vec3(0.0f);
    lo += (tie ? vec3(0.0f) : c) * r.lo;
    hi += (tie ? glm::max(c, edge) : c) * r.hi;
  }
}

}  // namespace

// A hard spot's edge (docs/compare.md, "Hard spots"): cos_axis = dot(-l, normalize(axis)) with
// l = normalize(light - p) is computed by each backend from the same p; two GLSL normalizes
// (inversesqrt 2 ULP, GLSL 4.50 §4.7.1), their products and the dot's sums move it by at most
// ~16 ULP of 1, 2^-20. Within that of cos outer the step may go either way.
LightSample hard_spot_lit_sample(const Light& light, LightModel model, const vec3& p) {
  if (!light.is_spot() || light.inner_cone_angle < light.outer_cone_angle) return {};
  const float cos_outer = std::cos(light.outer_cone_angle);
  const float cos_axis = glm::dot(-glm::normalize(light.position - p), glm::normalize(light.direction));
  if (std::fabs(cos_axis - cos_outer) > kHardSpotCosTie) return {};
  Light lit = light;  // the same light with the edge just outside p: the step's lit side
  lit.inner_cone_angle = lit.outer_cone_angle = std::min(std::acos(std::max(cos_axis - 2.0f * kHardSpotCosTie, -1.0f)),
                                                         0.5f * kPi);
  return sample_light(lit, model, p);
}

Image shading_tie_range(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps,
                        const VctSettings& settings, const Image& direct, const Image& emission) {
  const int w = g.coverage.width, h = g.coverage.height;
  Image out(w, h, 12);
  out.channel_names.clear();
  for (const char* group : kGroups)
    for (int c = 0; c < 3; ++c)
      for (bool upper : {false, true}) out.channel_names.push_back(tie_range_channel_name(group, c, upper));
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      vec3 lo(0.0f), hi(0.0f);
      if (g.coverage.at(x, y, 0) > 0.0f) direct_range_at(scene, g, maps, settings, x, y, lo, hi);
      const vec3 d = direct.empty() ? vec3(0.0f) : direct.rgb(x, y);
      const vec3 e = emission.empty() ? vec3(0.0f) : emission.rgb(x, y);
      for (int c = 0; c < 3; ++c) {
        // Channel order: group, channel, lo then hi (as the names above).
        out.at(x, y, 2 * c) = std::min(lo[c], d[c]);
        out.at(x, y, 2 * c + 1) = std::max(hi[c], d[c]);
        out.at(x, y, 6 + 2 * c) = e[c];
        out.at(x, y, 6 + 2 * c + 1) = e[c];
      }
    }
  });
  return out;
}

}  // namespace vct
