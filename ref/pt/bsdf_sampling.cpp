#include "pt/bsdf_sampling.h"

#include <algorithm>
#include <cmath>

namespace vct::pt {

namespace {
/// sin and cos of x for |x| <= pi/4 without libm: Cephes' minimax polynomials for that interval
/// (sinf.c, cosf.c; S. Moshier), within ~1 ulp there. A sampling map only has to be one fixed
/// function (its pdf is evaluated from the direction it returns, and its density differs from the
/// exact map's by ~1e-7 relatively), so these replace std::sin / std::cos, which cost ~3 % of a
/// path's time (docs/performance.md, "Issue 37, session 17").
void sincos_quarter(float x, float& s, float& c) {
  const float z = x * x;
  s = x + x * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
  c = 1.0f - 0.5f * z + z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
}

/// cos and sin of 2 pi t for t in [0, 1): the quadrant k = floor(4t) exactly, the angle b in it
/// folded to [0, pi/4] (cos b = sin(pi/2 - b)), then turned by k quarter turns (sign swaps).
vec2 cos_sin_turn(float t) {
  const float q = 4.0f * t;
  const int k = std::min(int(q), 3);
  const float b = (q - float(k)) * (0.5f * kPi);
  float s, c;
  if (b <= 0.25f * kPi)
    sincos_quarter(b, s, c);
  else
    sincos_quarter(0.5f * kPi - b, c, s);
  switch (k) {
    case 0: return vec2(c, s);
    case 1: return vec2(-s, c);
    case 2: return vec2(-c, -s);
    default: return vec2(s, -c);
  }
}
}  // namespace

vec3 sample_cosine_hemisphere(vec2 u) {
  // Concentric map of the unit square to the disk (Shirley-Chiu), then project up.
  const vec2 o = 2.0f * u - vec2(1.0f);
  vec2 d(0.0f);
  if (o.x != 0.0f || o.y != 0.0f) {
    // phi = pi/4 (o.y/o.x), or pi/2 - pi/4 (o.x/o.y) (cos and sin swap): |angle| <= pi/4 both ways.
    float s, c;
    if (std::abs(o.x) > std::abs(o.y)) {
      sincos_quarter(0.25f * kPi * (o.y / o.x), s, c);
      d = o.x * vec2(c, s);
    } else {
      sincos_quarter(0.25f * kPi * (o.x / o.y), s, c);
      d = o.y * vec2(s, c);
    }
  }
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return vec3(d.x, d.y, z);
}

float cosine_hemisphere_pdf(const vec3& l) { return l.z > 0.0f ? l.z * kInvPi : 0.0f; }

float smith_g1_ggx(const vec3& v, float alpha) {
  if (v.z <= 0.0f) return 0.0f;
  const float z2 = v.z * v.z;
  const float tan2 = std::max(0.0f, 1.0f - z2) / z2;
  return 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * tan2));
}

vec3 sample_ggx_vndf(const vec3& v, float alpha, vec2 u) {
  // Heitz 2018, listing 1 (isotropic alpha): stretch, sample the projected hemisphere, unstretch.
  const vec3 vh = glm::normalize(vec3(alpha * v.x, alpha * v.y, v.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = lensq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  const vec3 t2 = glm::cross(vh, t1);
  const float r = std::sqrt(u.x);
  const vec2 cs = cos_sin_turn(u.y);  // phi = 2 pi u.y
  const float p1 = r * cs.x;
  float p2 = r * cs.y;
  const float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
  const vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

float ggx_vndf_reflection_pdf(const vec3& v, const vec3& l, float roughness) {
  if (v.z <= 0.0f || l.z <= 0.0f) return 0.0f;
  const vec3 h = glm::normalize(v + l);
  const float alpha = roughness * roughness;
  return smith_g1_ggx(v, alpha) * sh::ggx_distribution(vec3(0.0f, 0.0f, 1.0f), h, roughness) / (4.0f * v.z);
}

namespace {
vec3 to_local(const sh::Frame& f, const vec3& w) { return vec3(glm::dot(w, f.t), glm::dot(w, f.b), glm::dot(w, f.n)); }
}  // namespace

BsdfPoint make_bsdf_point(const sh::SurfacePbr& pbr, const vec3& n, const vec3& ng, const vec3& v) {
  BsdfPoint p;
  p.pbr = pbr;
  p.n = n;
  p.ng = ng;
  p.v = v;
  p.frame = sh::frame_from_normal(n);
  p.v_local = to_local(p.frame, v);
  p.lambertian = pbr.f0 == vec3(0.0f) && pbr.f90 == 0.0f;
  // cook_torrance_lobes' diffuse expression with its Fresnel value, F = f0 + (f90 - f0) m^5 = 0.
  if (p.lambertian) p.lambert_diffuse = sh::diffuse_weight(pbr, vec3(0.0f)) * pbr.albedo * sh::SH_INV_PI;
  // Lobe choice by the lobes' expected weights at this view angle: Fresnel for the specular
  // lobe, kd * albedo for the diffuse one. Both lobes keep >= 5 % when both can contribute, so
  // neither mixture component's pdf can starve a direction the other lobe needs.
  const float n_dot_v = std::max(glm::dot(n, v), 0.0f);
  const float ws = luminance(sh::fresnel_schlick(pbr.f0, pbr.f90, n_dot_v));
  const float wd = luminance(pbr.albedo) * (1.0f - pbr.metallic) * std::max(0.0f, 1.0f - ws);
  if (ws <= 0.0f)
    p.specular_probability = 0.0f;
  else if (wd <= 0.0f)
    p.specular_probability = 1.0f;
  else
    p.specular_probability = std::clamp(ws / (ws + wd), 0.05f, 0.95f);
  // Only the specular lobe's pdf reads G1(v).
  if (p.specular_probability > 0.0f) p.g1_v = smith_g1_ggx(p.v_local, pbr.roughness * pbr.roughness);
  return p;
}

BsdfValue eval_bsdf(const BsdfPoint& p, const vec3& l) {
  BsdfValue out;
  if (glm::dot(p.ng, l) <= 0.0f) return out;  // reflection only: never through the surface
  if (p.lambertian) {
    // cook_torrance_lobes' own early exit, then its value with F = 0 (specular = 0 * finite).
    if (!(glm::dot(p.n, l) <= 0.0f || glm::dot(p.n, p.v) <= 0.0f)) out.diffuse = p.lambert_diffuse;
    return out;
  }
  const sh::BrdfLobes lobes = sh::cook_torrance_lobes(p.pbr, p.n, p.v, l);
  out.diffuse = lobes.diffuse;
  out.specular = lobes.specular;
  return out;
}

namespace {
/// The mixture pdf in world space: G1(v) D(h) / (4 n.v) for the specular lobe (Heitz 2018: the
/// VNDF sample reflected about h) and n.l / pi for the cosine lobe. h = normalize(v + l) and
/// D(n, h) are the very expressions sh::cook_torrance_lobes forms, so where both are evaluated
/// in one function (eval_bsdf with a pdf) the compiler computes them once.
inline float mixture_pdf(const BsdfPoint& p, const vec3& l) {
  const float n_dot_l = glm::dot(p.n, l);
  if (n_dot_l <= 0.0f) return 0.0f;
  float pdf = 0.0f;
  if (p.specular_probability > 0.0f && p.v_local.z > 0.0f)
    pdf += p.specular_probability *
           (p.g1_v * sh::ggx_distribution(p.n, glm::normalize(p.v + l), p.pbr.roughness) / (4.0f * p.v_local.z));
  if (p.specular_probability < 1.0f) pdf += (1.0f - p.specular_probability) * (n_dot_l * kInvPi);
  return pdf;
}
}  // namespace

float bsdf_pdf(const BsdfPoint& p, const vec3& l) { return mixture_pdf(p, l); }

BsdfValue eval_bsdf(const BsdfPoint& p, const vec3& l, float& pdf) {
  pdf = mixture_pdf(p, l);
  return eval_bsdf(p, l);
}

BsdfSample sample_bsdf(const BsdfPoint& p, float u_lobe, vec2 u) {
  BsdfSample s;
  const vec3& vl = p.v_local;
  if (vl.z <= 0.0f) return s;
  vec3 ll;
  if (u_lobe < p.specular_probability) {
    const vec3 h = sample_ggx_vndf(vl, p.pbr.roughness * p.pbr.roughness, u);
    ll = 2.0f * glm::dot(vl, h) * h - vl;
  } else {
    ll = sample_cosine_hemisphere(u);
  }
  if (ll.z <= 0.0f) return s;
  s.l = glm::normalize(sh::frame_to_world(p.frame, ll));
  s.f = eval_bsdf(p, s.l, s.pdf);
  s.valid = s.pdf > 0.0f;
  return s;
}

}  // namespace vct::pt
