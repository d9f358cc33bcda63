#include "attribution/specular_ladder.h"

#include "attribution/attribution.h"

#include <algorithm>
#include <cmath>

#include "pt/bsdf_sampling.h"
#include "pt/rng.h"
#include "stages/cone_sets.h"

namespace vct::attr {

namespace {
constexpr uint32_t kSaltGgx = 21, kSaltSpecularCone = 22;

vec3 to_local(const sh::Frame& f, const vec3& w) { return vec3(glm::dot(w, f.t), glm::dot(w, f.b), glm::dot(w, f.n)); }
}  // namespace

const std::vector<std::string>& specular_term_names() {
  static const std::vector<std::string> names = {"voxel_field", "cone_for_lobe", "cone_step_schedule", "mip_lookups"};
  return names;
}

RungImage gather_ggx_rays(const LadderContext& ctx, uint32_t stream) {
  const uint32_t seed = ctx.settings().pt.seed;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    pt::Pcg32 rng(pixel_seed(s.x, s.y, ctx.width(), stream, seed, kSaltGgx), stream);
    const pt::BsdfPoint bsdf = pt::make_bsdf_point(s.pbr, s.n, s.n, s.v);
    const vec3 vl = to_local(bsdf.frame, s.v);
    const vec3 origin = ctx.march().origin_at(ctx.scene().volume.to_texture(s.p), s.n);
    const float alpha = s.pbr.roughness * s.pbr.roughness;
    PixelSamples acc;
    for (int i = 0; i < ctx.rays_per_pixel(); ++i) {
      vec3 value(0.0f);  // a reflection below the horizon contributes 0 (still one sample)
      if (vl.z > 0.0f) {
        const vec3 h = pt::sample_ggx_vndf(vl, alpha, rng.next_2d());
        const vec3 ll = 2.0f * glm::dot(vl, h) * h - vl;
        const float pdf = pt::ggx_vndf_reflection_pdf(vl, ll, s.pbr.roughness);
        if (ll.z > 0.0f && pdf > 0.0f) {
          const vec3 l = glm::normalize(sh::frame_to_world(bsdf.frame, ll));
          const vec3 radiance = base_level_ray(ctx.mips(), ctx.march(), origin, l);
          value = pt::eval_bsdf(bsdf, l).specular * std::max(glm::dot(s.n, l), 0.0f) * radiance / pdf;
        }
      }
      acc.add(value);
    }
    acc.store(out, s.x, s.y);
  });
}

RungImage gather_specular_cone_rays(const LadderContext& ctx, uint32_t stream) {
  const uint32_t seed = ctx.settings().pt.seed;
  const bool on = ctx.settings().vct.specular_cones;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    if (!on) return;  // the frame traces no specular cone: nothing to stand in for
    pt::Pcg32 rng(pixel_seed(s.x, s.y, ctx.width(), stream, seed, kSaltSpecularCone), stream);
    // The frame's cone (stages/cone_sets.h): axis reflect(-v, n), aperture from roughness.
    const Cone cone = specular_cone(ctx.scene().volume, s.p, s.n, s.v, s.pbr.roughness, ctx.march().normal_offset);
    PixelSamples acc;
    for (int i = 0; i < ctx.rays_per_pixel(); ++i) {
      const vec3 l = direction_in_cone(cone.direction, cone.aperture, rng.next_2d());
      acc.add(s.fresnel * base_level_ray(ctx.mips(), ctx.march(), cone.origin, l));
    }
    acc.store(out, s.x, s.y);
  });
}

RungImage specular_cone_base_level_steps(const LadderContext& ctx) {
  const bool on = ctx.settings().vct.specular_cones;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    if (!on) return;
    const Cone cone = specular_cone(ctx.scene().volume, s.p, s.n, s.v, s.pbr.roughness, ctx.march().normal_offset);
    out.value.set_rgb(s.x, s.y, s.fresnel * base_level_cone_steps(ctx.mips(), ctx.march(), cone));
  });
}

std::vector<Rung> specular_rungs(const LadderContext& ctx) {
  check_attributable(ctx.settings().vct);  // an engine's conventions are judged, not split (issue 21)
  const LadderContext* c = &ctx;
  return {
      {"truth", "path tracer, one-bounce specular (pt_indirect_specular)", false,
       [c](uint32_t st) { return path_traced_rung(c->path_traced(st), pt::kIndirectSpecular); }},
      {"ggx_lobe_rays", "GGX-lobe rays through the base voxel level, f_s cos L / pdf", false,
       [c](uint32_t st) { return gather_ggx_rays(*c, st); }},
      {"cone_rays", "rays inside the specular cone through the base level, x F(n.v)", false,
       [c](uint32_t st) { return gather_specular_cone_rays(*c, st); }},
      {"cone_steps", "the cone's own growing steps on its axis, base level (no mips), x F(n.v)", true,
       [c](uint32_t) { return specular_cone_base_level_steps(*c); }},
      {"vct", "the frame's specular_term (the cone on the mips)", true,
       [c](uint32_t) { return image_rung(c->frame().images.specular_term, c->mask()); }},
  };
}

}  // namespace vct::attr
