#include "attribution/direct_ladder.h"

#include <cmath>
#include <limits>

#include "stages/light_sample.h"

namespace vct::attr {

const std::vector<std::string>& direct_term_names() {
  static const std::vector<std::string> names = {"gbuffer_point", "shadow_visibility"};
  return names;
}

namespace {

// Offsets as the path tracer's (pt/integrator.cpp): 1e-4 of the scene's extent along the normal,
// and a sun's shadow ray long enough to leave the scene from any point.
bool light_visible(const pt::EmbreeScene& rt, const vec3& p, const vec3& n, const LightSample& ls, float scale) {
  const float eps = 1e-4f * scale;
  const vec3 org = p + n * eps;
  const float length = std::isfinite(ls.distance) ? ls.distance - 2.0f * eps : 4.0f * scale;
  if (!(length > 0.0f)) return true;
  return !rt.occluded(org, ls.l, 0.0f, length);
}

}  // namespace

RungImage direct_exact_visibility(const LadderContext& ctx) {
  const Scene& scene = ctx.scene();
  const VctSettings& vs = ctx.settings().vct;
  const pt::EmbreeScene& rt = ctx.embree();
  const float scale = scene.volume.size;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    vec3 sum(0.0f);
    // The sum of stages/direct.cpp direct_radiance, with an exact shadow ray for visibility.
    for (const Light& light : scene.lights) {
      const LightSample ls = sample_light(light, vs.light_model, s.p);
      const float n_dot_l = glm::dot(s.n, ls.l);
      if (n_dot_l <= 0.0f || ls.irradiance == vec3(0.0f)) continue;
      if (!light_visible(rt, s.p, s.n, ls, scale)) continue;
      sum += sh::cook_torrance(s.pbr, s.n, s.v, ls.l) * ls.irradiance * n_dot_l;
    }
    out.value.set_rgb(s.x, s.y, sum);
  });
}

std::vector<Rung> direct_rungs(const LadderContext& ctx) {
  const LadderContext* c = &ctx;
  return {
      {"truth", "path tracer, direct light (pt_direct)", false,
       [c](uint32_t st) { return path_traced_rung(c->path_traced(st), pt::kDirect); }},
      {"exact_visibility", "the frame's shading at the G-buffer points, Embree shadow rays", true,
       [c](uint32_t) { return direct_exact_visibility(*c); }},
      {"vct", "the frame's direct image (shadow map + PCF, or cone shadows)", true,
       [c](uint32_t) { return image_rung(c->frame().images.direct, c->mask()); }},
  };
}

}  // namespace vct::attr
