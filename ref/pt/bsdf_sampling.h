// Importance sampling of the pipelines' Cook–Torrance BRDF (vct::sh::cook_torrance): a mixture of
// a cosine-weighted diffuse lobe and GGX visible-normal sampling (Heitz 2018, "Sampling the GGX
// Distribution of Visible Normals"), with the mixture pdf. The BRDF *values* always come from
// vct_shared.h; this file only decides where to look and with which density.
#pragma once

#include "core/math.h"
#include "shared/vct_shared.h"

namespace vct::pt {

// ---- Single-lobe samplers in a local frame (z = normal). Each has its pdf (solid angle). ----

/// Cosine-weighted direction on the upper hemisphere (Malley: concentric disk, lifted).
vec3 sample_cosine_hemisphere(vec2 u);
float cosine_hemisphere_pdf(const vec3& l);

/// Smith G1 of the isotropic GGX distribution with roughness alpha (exact, not Schlick's).
float smith_g1_ggx(const vec3& v, float alpha);
/// A microfacet normal distributed by the visible normals D_v(h) = G1(v) max(0,v.h) D(h) / v.z.
vec3 sample_ggx_vndf(const vec3& v, float alpha, vec2 u);
/// pdf of l = reflect(v about h) when h ~ D_v: D_v(h) / (4 v.h) = G1(v) D(h) / (4 v.z).
/// D is sh::ggx_distribution(., roughness), alpha = roughness^2 as in the BRDF.
float ggx_vndf_reflection_pdf(const vec3& v, const vec3& l, float roughness);

// ---- The mixture at a shading point (world space). ----

/// A shading point as the estimator sees it. n is the shading normal and ng the geometric
/// normal, both already turned to the side v is on; directions below ng's plane are never
/// sampled or lit (no light leaks through a surface whose shading normal is bent).
struct BsdfPoint {
  sh::SurfacePbr pbr;
  vec3 n;
  vec3 ng;
  vec3 v;
  sh::Frame frame;  // around n
  vec3 v_local{0.0f};  // v in `frame` (sample_bsdf and bsdf_pdf read it for every direction)
  float g1_v = 0.0f;   // smith_g1_ggx(v_local, roughness^2) where the specular lobe is sampled
  float specular_probability = 0.0f;
  // Fresnel identically 0 (f0 = 0 and f90 = 0, e.g. KHR_materials_specular factor 0): the
  // specular lobe is exactly 0 and the diffuse lobe the constant kd albedo / pi, which eval_bsdf
  // then returns without the half vector, D and G (the same bits as sh::cook_torrance_lobes:
  // docs/performance.md "Shading per ray").
  bool lambertian = false;
  vec3 lambert_diffuse{0.0f};
};

BsdfPoint make_bsdf_point(const sh::SurfacePbr& pbr, const vec3& n, const vec3& ng, const vec3& v);

/// cook_torrance split into its two lobes: diffuse = kd(h) albedo / pi, specular = the rest.
struct BsdfValue {
  vec3 diffuse{0.0f};
  vec3 specular{0.0f};
  vec3 total() const { return diffuse + specular; }
};
BsdfValue eval_bsdf(const BsdfPoint& p, const vec3& l);
/// The same and the mixture pdf of l (bsdf_pdf) at once: they share the half vector and D.
BsdfValue eval_bsdf(const BsdfPoint& p, const vec3& l, float& pdf);

/// Mixture pdf (solid angle) of sample_bsdf producing l, formed in world space (issue 37, session
/// 17; it was formed in the local frame before: the same density, other roundings).
float bsdf_pdf(const BsdfPoint& p, const vec3& l);

struct BsdfSample {
  vec3 l{0.0f};
  float pdf = 0.0f;
  BsdfValue f;  // eval_bsdf(l), formed with the pdf
  bool valid = false;  // false: the specular lobe reflected below the horizon (weight 0)
};
/// u_lobe picks the lobe, u the direction.
BsdfSample sample_bsdf(const BsdfPoint& p, float u_lobe, vec2 u);

inline float luminance(const vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace vct::pt
