#include "attribution/diffuse_ladder.h"

#include "attribution/attribution.h"

#include <cmath>

#include "core/error.h"
#include "pt/bsdf_sampling.h"
#include "pt/rng.h"
#include "stages/cone_sets.h"

namespace vct::attr {

namespace {
// Salts keep the rungs' random numbers apart even within one stream.
constexpr uint32_t kSaltCosine = 11, kSaltCosineKd = 13, kSaltCones = 12;
}  // namespace

const std::vector<std::string>& diffuse_term_names() {
  static const std::vector<std::string> names = {"voxel_field", "kd_at_n_dot_v", "cone_quadrature",
                                                 "cone_step_schedule", "mip_lookups"};
  return names;
}

RungImage gather_cosine_rays(const LadderContext& ctx, uint32_t stream, bool composite_kd) {
  const uint32_t seed = ctx.settings().pt.seed;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    pt::Pcg32 rng(pixel_seed(s.x, s.y, ctx.width(), stream, seed, composite_kd ? kSaltCosineKd : kSaltCosine), stream);
    const sh::Frame frame = sh::frame_from_normal(s.n);
    const pt::BsdfPoint bsdf = pt::make_bsdf_point(s.pbr, s.n, s.n, s.v);
    const vec3 origin = ctx.march().origin_at(ctx.scene().volume.to_texture(s.p), s.n);
    PixelSamples acc;
    for (int i = 0; i < ctx.rays_per_pixel(); ++i) {
      const vec3 l = glm::normalize(sh::frame_to_world(frame, pt::sample_cosine_hemisphere(rng.next_2d())));
      const vec3 radiance = base_level_ray(ctx.mips(), ctx.march(), origin, l);
      // pdf = cos / pi, so f cos L / pdf = pi f L.
      acc.add(composite_kd ? s.kd_albedo * radiance : kPi * pt::eval_bsdf(bsdf, l).diffuse * radiance);
    }
    acc.store(out, s.x, s.y);
  });
}

RungImage gather_cone_set_rays(const LadderContext& ctx, uint32_t stream) {
  const VctSettings& vs = ctx.settings().vct;
  const sh::DiffuseConeBlock block = diffuse_cone_block(vs);
  const int count = sh::diffuse_cone_count(block);
  const float aperture = vs.diffuse_aperture_deg * (kPi / 180.0f);
  const uint32_t seed = ctx.settings().pt.seed;
  const bool on = vs.diffuse_cones;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    if (!on) return;  // the frame traces no diffuse cones: the quadrature term takes it all
    pt::Pcg32 rng(pixel_seed(s.x, s.y, ctx.width(), stream, seed, kSaltCones), stream);
    const sh::Frame frame = sh::frame_from_normal(s.n);
    const float rotation = diffuse_rotation_for_pixel(vs, s.x, s.y);  // the frame's rotation
    const vec3 origin = ctx.march().origin_at(ctx.scene().volume.to_texture(s.p), s.n);
    PixelSamples acc;
    // One sample = one ray in every cone, combined with the set's weights: an unbiased estimate
    // of the weighted sum of the cones' mean radiance (each cone's interior uniformly in solid angle).
    for (int i = 0; i < ctx.rays_per_pixel(); ++i) {
      vec3 sum(0.0f);
      for (int c = 0; c < count; ++c) {
        const vec3 axis = glm::normalize(sh::frame_to_world(frame, sh::diffuse_cone_direction(c, rotation, block)));
        const vec3 l = direction_in_cone(axis, aperture, rng.next_2d());
        sum += sh::diffuse_cone_weight(c, block) * base_level_ray(ctx.mips(), ctx.march(), origin, l);
      }
      acc.add(s.kd_albedo * sum);
    }
    acc.store(out, s.x, s.y);
  });
}

RungImage cone_set_base_level_steps(const LadderContext& ctx) {
  const VctSettings& vs = ctx.settings().vct;
  const sh::DiffuseConeBlock block = diffuse_cone_block(vs);
  const int count = sh::diffuse_cone_count(block);
  const float aperture = vs.diffuse_aperture_deg * (kPi / 180.0f);
  const bool on = vs.diffuse_cones;
  return ctx.for_each_pixel([&](const PixelSurface& s, RungImage& out) {
    if (!on) return;
    const sh::Frame frame = sh::frame_from_normal(s.n);
    const float rotation = diffuse_rotation_for_pixel(vs, s.x, s.y);
    vec3 sum(0.0f);
    for (int c = 0; c < count; ++c) {
      Cone cone;
      cone.origin = ctx.march().origin_at(ctx.scene().volume.to_texture(s.p), s.n);
      cone.direction = glm::normalize(sh::frame_to_world(frame, sh::diffuse_cone_direction(c, rotation, block)));
      cone.aperture = aperture;
      sum += sh::diffuse_cone_weight(c, block) * base_level_cone_steps(ctx.mips(), ctx.march(), cone);
    }
    out.value.set_rgb(s.x, s.y, s.kd_albedo * sum);
  });
}

std::vector<Rung> diffuse_rungs(const LadderContext& ctx) {
  const VctSettings& vs = ctx.settings().vct;
  // The ladders split the oracle's own cones and composite; an engine's conventions (issue 21) are
  // judged by vct compare, not attributed (attribution.h check_attributable).
  check_attributable(vs);
  const LadderContext* c = &ctx;
  return {
      {"truth", "path tracer, one-bounce diffuse (pt_indirect_diffuse)", false,
       [c](uint32_t st) { return path_traced_rung(c->path_traced(st), pt::kIndirectDiffuse); }},
      {"exact_gathering", "cosine rays through the base voxel level, pi f_d L", false,
       [c](uint32_t st) { return gather_cosine_rays(*c, st, false); }},
      {"composite_kd", "the same rays' radiance x kd(n.v) albedo", false,
       [c](uint32_t st) { return gather_cosine_rays(*c, st, true); }},
      {"cone_set_rays", "rays inside each diffuse cone through the base level, cone weights", false,
       [c](uint32_t st) { return gather_cone_set_rays(*c, st); }},
      {"cone_steps", "each cone's own growing steps on its axis, base level (no mips)", true,
       [c](uint32_t) { return cone_set_base_level_steps(*c); }},
      {"vct", "the frame's diffuse_term (cones on the mips)", true,
       [c](uint32_t) { return image_rung(c->frame().images.diffuse_term, c->mask()); }},
  };
}

}  // namespace vct::attr
