// The gathering rungs on hand-made voxel fields whose answer is known (docs/attribution.md, "Tests").
#include <gtest/gtest.h>

#include <cmath>

#include "attribution/diffuse_ladder.h"
#include "attribution/specular_ladder.h"
#include "pt/bsdf_sampling.h"
#include "pt/rng.h"
#include "attribution/ladder_context.h"
#include "stages/composite.h"
#include "stages/indirect_pass.h"
#include "stages/mips.h"

namespace vct::attr {
namespace {

constexpr float kRadiance = 2.0f;
constexpr float kAlbedo = 0.8f;

// One covered pixel at world = texture point p with normal +z, looked at from above.
struct OnePixel {
  Scene scene;
  Settings settings;
  FrameResult frame;
};

OnePixel one_pixel(const Volume& base, const vec3& p) {
  OnePixel o;
  o.scene.volume.origin = vec3(0.0f);
  o.scene.volume.size = 1.0f;
  o.scene.camera.position = p + vec3(0.0f, -0.3f, 0.4f);
  o.settings.vct.width = o.settings.vct.height = 1;
  o.settings.vct.grid = base.nx;
  o.settings.vct.random_rotation = false;
  GBuffer& g = o.frame.gbuffer;
  const auto image = [](int c, float fill) { return Image(1, 1, c, fill); };
  g.position = image(3, 0.0f);
  g.position.set_rgb(0, 0, p);
  g.normal = image(3, 0.0f);
  g.normal.set_rgb(0, 0, vec3(0.0f, 0.0f, 1.0f));
  g.albedo = image(3, kAlbedo);
  g.material = image(4, 0.0f);
  g.material.at(0, 0, 1) = 0.5f;  // roughness
  g.material.at(0, 0, 2) = 1.0f;  // specular_factor
  g.specular_color = image(3, 1.0f);
  g.emission = image(3, 0.0f);
  g.coverage = image(1, 1.0f);
  o.frame.mips = build_mips(base, false);
  IndirectImages ind = trace_indirect(o.scene, g, o.frame.mips, o.settings.vct);
  o.frame.images.indirect_diffuse = ind.diffuse;
  o.frame.images.indirect_specular = ind.specular;
  composite_frame(o.scene, g, o.settings.vct, o.frame.images);
  return o;
}

// Opaque voxels of radiance kRadiance (premultiplied: rgb = L x alpha) where z index >= from_k.
Volume ceiling(int n, int from_k) {
  Volume v(n, n, n, 4);
  for (int k = from_k; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        float* t = &v.data[v.index(i, j, k)];
        t[0] = t[1] = t[2] = kRadiance;
        t[3] = 1.0f;
      }
  return v;
}

// Form factor from a point to a parallel square of half-width w centred above it at height h:
// four corner rectangles, F = 1/(2 pi) [X/sqrt(1+X^2) atan(X/sqrt(1+X^2)) x 2] each, X = w/h.
double square_form_factor(double w, double h) {
  const double x = w / h, r = x / std::sqrt(1.0 + x * x);
  return 4.0 * (2.0 * r * std::atan(r)) / (2.0 * 3.14159265358979323846);
}

// The composite's factors: diffuse_term with indirect_diffuse = 1 is kd albedo, specular_term
// with indirect_specular = 1 is F(n.v).
FrameImages unit_composite(const OnePixel& o) {
  FrameImages im;
  im.indirect_diffuse = Image(1, 1, 3, 1.0f);
  im.indirect_specular = Image(1, 1, 3, 1.0f);
  composite_frame(o.scene, o.frame.gbuffer, o.settings.vct, im);
  return im;
}
double kd_albedo_of(const OnePixel& o) { return luminance(unit_composite(o).diffuse_term.rgb(0, 0)); }
double fresnel_of(const OnePixel& o) { return luminance(unit_composite(o).specular_term.rgb(0, 0)); }

// Every voxel opaque with radiance L: every ray and every cone returns exactly L (its first sample
// is opaque, rgb / alpha = L), so the composite-kd rung, the cone-set rung, the cones' base-level
// steps and VCT all equal
// kd albedo L, with no variance beyond float rounding (the trilinear weights and the cosine
// weights each sum to 1 only to a few ulps: 1e-6 relative is ~16 float ulps).
TEST(LadderAnalytic, OpaqueFurnaceAllVoxelRungsAgree) {
  const OnePixel o = one_pixel(ceiling(16, 0), vec3(0.5f, 0.5f, 0.5f));
  const LadderContext ctx(o.scene, o.settings, o.frame, 16);
  const double expected = kd_albedo_of(o) * double(kRadiance);
  ASSERT_GT(expected, 0.5);
  const MeanSe gather = masked_mean(gather_cosine_rays(ctx, kStreamA, true), ctx.mask());
  const MeanSe cones = masked_mean(gather_cone_set_rays(ctx, kStreamA), ctx.mask());
  const MeanSe steps = masked_mean(cone_set_base_level_steps(ctx), ctx.mask());
  const MeanSe vct = masked_mean(image_rung(o.frame.images.diffuse_term, ctx.mask()), ctx.mask());
  EXPECT_NEAR(steps.mean, expected, 1e-5 * expected);
  EXPECT_NEAR(gather.mean, expected, 1e-6 * expected);
  EXPECT_LT(gather.se, 1e-6 * expected);
  EXPECT_NEAR(cones.mean, expected, 1e-5 * expected);  // five weights summed in float
  EXPECT_LT(cones.se, 1e-6 * expected);
  EXPECT_NEAR(vct.mean, expected, 1e-5 * expected);
}

// The same furnace for the specular cone: rays inside it and the cone itself both return L, so
// both rungs are F(n.v) L (same tolerances as above).
TEST(LadderAnalytic, OpaqueFurnaceSpecularConeRungsAgree) {
  const OnePixel o = one_pixel(ceiling(16, 0), vec3(0.5f, 0.5f, 0.5f));
  const LadderContext ctx(o.scene, o.settings, o.frame, 16);
  const double expected = fresnel_of(o) * double(kRadiance);
  ASSERT_GT(expected, 0.05);
  const MeanSe rays = masked_mean(gather_specular_cone_rays(ctx, kStreamA), ctx.mask());
  const MeanSe steps = masked_mean(specular_cone_base_level_steps(ctx), ctx.mask());
  const MeanSe vct = masked_mean(image_rung(o.frame.images.specular_term, ctx.mask()), ctx.mask());
  EXPECT_NEAR(steps.mean, expected, 1e-6 * expected);
  EXPECT_NEAR(rays.mean, expected, 1e-6 * expected);
  EXPECT_LT(rays.se, 1e-6 * expected);
  EXPECT_NEAR(vct.mean, expected, 1e-5 * expected);
}

// An independent estimate of L x the integral of one lobe's f cos over the hemisphere at the
// one pixel (uniform hemisphere directions, 2 pi f cos, 200000 samples): mean and SE.
MeanSe uniform_lobe_albedo(const OnePixel& o, bool specular) {
  const GBuffer& g = o.frame.gbuffer;
  const sh::SurfacePbr pbr = sh::surface_pbr(g.albedo.rgb(0, 0), g.material.at(0, 0, 0), g.material.at(0, 0, 1),
                                             g.material.at(0, 0, 2), g.specular_color.rgb(0, 0));
  const vec3 n(0.0f, 0.0f, 1.0f), v = o.scene.camera.to_eye(g.position.rgb(0, 0));
  const pt::BsdfPoint bsdf = pt::make_bsdf_point(pbr, n, n, v);
  pt::Pcg32 rng(99, 5);
  const int count = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < count; ++i) {
    const vec2 u = rng.next_2d();
    const float z = u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
    const vec3 l(r * std::cos(phi), r * std::sin(phi), z);  // uniform on the upper hemisphere
    const pt::BsdfValue f = pt::eval_bsdf(bsdf, l);
    const double y = luminance(specular ? f.specular : f.diffuse) * double(z) * 2.0 * double(kPi) * double(kRadiance);
    sum += y;
    sum2 += y * y;
  }
  MeanSe m;
  m.mean = sum / count;
  m.se = std::sqrt((sum2 / count - m.mean * m.mean) / (count - 1));
  return m;
}

// In the furnace every ray returns L, so the importance-sampled gathering rungs are L x their
// lobe's directional albedo: the GGX-lobe rung (visible-normal sampling, its pdf) and the
// exact-gathering rung (cosine sampling, pi f_d). Each must agree with the uniform estimate within
// 4 combined SE, a bound under 5 % of the value, so a wrong pdf or weight would not pass.
TEST(LadderAnalytic, OpaqueFurnaceImportanceSampledRungsGiveTheLobeAlbedos) {
  const OnePixel o = one_pixel(ceiling(16, 0), vec3(0.5f, 0.5f, 0.5f));
  const LadderContext ctx(o.scene, o.settings, o.frame, 4096);
  const std::pair<MeanSe, MeanSe> cases[] = {
      {masked_mean(gather_ggx_rays(ctx, kStreamA), ctx.mask()), uniform_lobe_albedo(o, true)},
      {masked_mean(gather_cosine_rays(ctx, kStreamA, false), ctx.mask()), uniform_lobe_albedo(o, false)}};
  for (const auto& [rung, reference] : cases) {
    ASSERT_GT(reference.mean, 0.01);
    const double bound = 4.0 * std::sqrt(rung.se * rung.se + reference.se * reference.se);
    EXPECT_NEAR(rung.mean, reference.mean, bound);
    EXPECT_LT(bound, 0.05 * reference.mean) << "too few samples to tell a wrong pdf";
  }
}

// An opaque ceiling (z >= 1/2) over a point at z = 0.1 in the middle of a 64^3 volume: the
// cosine-weighted fraction of rays that reach it is the form factor of the square the volume's
// sides cut from it. Trilinear filtering blurs the ceiling's face by half a voxel, and the march
// stops at the volume's sides, so the gathered mean lies between kd albedo L F for
//  - lower: the square shrunk by 3 voxels at height 33/64 - 0.1: a ray crossing z = 33/64 inside it
//    has a sample in the fully opaque zone z >= 32.5/64 (rays at >= 29 degrees of elevation
//    move <= 1.8 voxels sideways per voxel of height, steps are half a voxel), so it returns L;
//  - upper: the full square at height 31.5/64 - 0.1, below which alpha is 0 (a ray that crosses
//    z = 31.5/64 outside the square has left the volume and gathers nothing more);
// widened by 4 standard errors of the Monte Carlo mean.
TEST(LadderAnalytic, CeilingFormFactorBoundsTheCosineGathering) {
  const int n = 64;
  const OnePixel o = one_pixel(ceiling(n, n / 2), vec3(0.5f, 0.5f, 0.1f));
  const LadderContext ctx(o.scene, o.settings, o.frame, 4096);
  const double kl = kd_albedo_of(o) * double(kRadiance);
  const double lower = kl * square_form_factor(0.5 - 3.0 / n, 33.0 / n - 0.1);
  const double upper = kl * square_form_factor(0.5, 31.5 / n - 0.1);
  const MeanSe gather = masked_mean(gather_cosine_rays(ctx, kStreamA, true), ctx.mask());
  ASSERT_GT(gather.se, 0.0);
  EXPECT_GT(gather.mean, lower - 4.0 * gather.se);
  EXPECT_LT(gather.mean, upper + 4.0 * gather.se);
  // The band is narrow enough to catch a wrong sampler: uniform hemisphere sampling would give
  // the solid-angle fraction instead (about 0.42 here, against a form factor of about 0.66).
  EXPECT_LT(upper - lower, 0.12 * kl);
}

}  // namespace
}  // namespace vct::attr
