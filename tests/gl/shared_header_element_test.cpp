// Element tests of the shared header: every function of ref/shared/vct_shared.h and
// voxel_fixed_point.h evaluated in GLSL on a deterministic grid (edge cases included) and compared
// element by element with the C++ build of the same header (shared_header_harness.h). Integer and
// hash functions must agree bit for bit; float functions within a per-point bound derived from the
// GLSL 4.50 precision rules (§4.7.1). The derivation of each bound is in docs/compare.md
// ("Shared-header element tests"); the budgets below use its notation: u = 2^-24 (half an ulp at
// 1), an operation's budget is its relative error in units of u, GL and C++ budgets add up.
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>

#include "gl_test_util.h"
#include "shared/vct_shared.h"
#include "shared/voxel_fixed_point.h"
#include "shared_header_harness.h"

namespace vct::gl::test {
namespace {

using glm::uvec4;
using glm::vec3;
using glm::vec4;

constexpr double kU = 1.0 / 16777216.0;  // 2^-24
// Per-operation budgets in u (docs/compare.md): GLSL 4.50 §4.7.1 makes + - * and conversions
// correctly rounded (1 u; a contracted a*b+c is no worse), a/b 2.5 ulp (5 u), inversesqrt 2 ulp
// (4 u); the C++ side (IEEE binary32, no -ffast-math) rounds every operation correctly (1 u).
constexpr double kGlDiv = 5.0, kCpuDiv = 1.0;
// normalize(v) = v * inversesqrt(dot(v, v)): dot 3 u, inversesqrt 4 u + half of 3 u, product 1 u
// = 9.5 u per component (GL); C++ (glm: 1/sqrt) 3 + 1.5 + 1 + 1 = 6.5 u. Unit result, so 16 u
// absolute per component, 16*sqrt(3) u in norm between the two sides.
constexpr double kNormalizeNorm = 16.0 * 1.7320508;
// sin, cos, atan: GLSL 4.50 leaves their precision undefined (§4.7.1, last rule). We take the
// bounds Vulkan 1.3 states for the same GLSL.std.450 instructions (appendix "Precision and
// Operation of SPIR-V Instructions"): sin/cos absolute 2^-11, atan 4096 ulp (8192 u); glibc's
// sinf/cosf/atanf are within 1 ulp (2 u).
constexpr double kGlSinCosAbs = 1.0 / 2048.0, kGlAtanU = 8192.0, kCpuLibmU = 2.0;

ExpectedSlot exact(const vec4& v) {
  return {words(v), vec4(0.0f)};
}
ExpectedSlot exact_u(const uvec4& v) {
  return {v, vec4(0.0f)};
}
ExpectedSlot within(const vec4& v, const glm::dvec4& bound) {
  return {words(v), vec4(bound)};
}

// ---- input grids -------------------------------------------------------------------------------

std::vector<uint32_t> hash_keys() {
  std::vector<uint32_t> k = {0u,          1u,          2u,          3u,          255u,
                             256u,        65535u,      65536u,      0x7fffffffu, 0x80000000u,
                             0xfffffffeu, 0xffffffffu, 0x9E3779B9u, 0xDEADBEEFu};
  for (uint32_t i = 0; i < 250; ++i) k.push_back(sh::pcg_hash(i * 7919u));
  return k;
}

// Unit normals: the axes (both signs, including -z where frame_from_normal switches branch),
// diagonals, nearly-axis vectors and a Fibonacci sphere.
std::vector<vec3> normals() {
  std::vector<vec3> n = {{0, 0, 1},
                         {0, 0, -1},
                         {1, 0, 0},
                         {-1, 0, 0},
                         {0, 1, 0},
                         {0, -1, 0},
                         {1e-4f, 0, -1},
                         {0, 1e-3f, 1},
                         {0.577350269f, 0.577350269f, 0.577350269f},
                         {-0.577350269f, 0.577350269f, -0.577350269f}};
  for (auto& v : n) v = glm::normalize(v);
  for (int i = 0; i < 40; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 40.0, r = std::sqrt(1.0 - z * z),
                 phi = 2.399963229728653 * i;
    n.push_back(vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
  }
  return n;
}

// A direction at polar angle theta from unit n (azimuth phi), built in double, rounded to float.
vec3 around(const vec3& n, double theta, double phi) {
  const glm::dvec3 nd(n), a = std::abs(nd.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(a, nd)), b = glm::cross(nd, t);
  return vec3(std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b) + std::cos(theta) * nd);
}

const std::vector<double> kThetas = {0.0, 1e-4, 1e-3, 0.01,  0.05,      0.2, 0.5,
                                     1.0, 1.3,  1.5,  1.569, 1.5707963, 2.0, 3.1};
const std::vector<float> kRoughness = {
    0.0f, 0.001f, sh::MIN_ROUGHNESS, 0.05f, 0.1f, 0.3f, 0.5f, 0.8f, 0.99f, 1.0f};

// ---- bounds shared by the BRDF cases -------------------------------------------------------

// Relative bound (in u) of ggx_distribution between the sides, for inputs exact on both sides but
// for an absolute difference eps_h (norm, in u) in h. D = a2 / (pi d^2), d = cos2 a2 + sin2:
// a2 3 u; |n x h|_i has absolute error 2 u (|n_j h_k| + |n_k h_j|) (cancels near the peak);
// sin2 = sum x_i^2; cos2 = c^2 with c's absolute error 3 u; then 2 dd/d plus the final ops.
double ggx_rel_bound_u(const vec3& n, const vec3& h, float roughness, double eps_h) {
  const glm::dvec3 nd(n), hd(h);
  const double a2 = std::pow(double(roughness), 4.0), c = glm::dot(nd, hd);
  const glm::dvec3 x = glm::cross(nd, hd);
  const glm::dvec3 p(std::abs(nd.y * hd.z) + std::abs(nd.z * hd.y),
                     std::abs(nd.z * hd.x) + std::abs(nd.x * hd.z),
                     std::abs(nd.x * hd.y) + std::abs(nd.y * hd.x));
  const double sin2 = glm::dot(x, x);
  const double dsin2 =
      4.0 * (std::abs(x.x) * p.x + std::abs(x.y) * p.y + std::abs(x.z) * p.z) + 3.0 * sin2;
  const double d = c > 0.0 ? c * c * a2 + sin2 : 1.0;
  // c <= 0 in double but |c| < 3 u: one side may take the c > 0 branch, where d = c^2 a2 + sin2
  // differs from 1 by O(u) (sin2 = 1 - c^2): the same per-side formula with |c| covers it.
  const double dd_side = a2 * 7.0 * std::abs(c) + 4.0 * c * c * a2 + dsin2 + d;
  const double dd_h = 2.0 * eps_h * (a2 * std::abs(c) + std::sqrt(sin2));
  const double d_floor = std::max(d, 1e-300);
  // a2 (3 u) + pi*d*d (2 u) + division, each side; 2 dd/d each side; 2 dd_h/d once.
  return 3 + 2 + kGlDiv + 3 + 2 + kCpuDiv + 4.0 * dd_side / d_floor + 2.0 * dd_h / d_floor;
}

// fresnel_schlick: m = clamp(1 - cos) 1 u, m^5 9 u, (f90 - f0) 1 u, product 1 u, sum 1 u: 12 u
// per side of S = |f0| + |(f90 - f0) m^5|; a difference dcos (absolute, in u) in cos adds
// 5 |f90 - f0| m^4 dcos.
glm::dvec3 fresnel_bound(const vec3& f0, float f90, float cos_theta, double dcos) {
  const double m = std::clamp(1.0 - double(cos_theta), 0.0, 1.0);
  glm::dvec3 b;
  for (int i = 0; i < 3; ++i) {
    const double span = std::abs(double(f90) - double(f0[i]));
    b[i] = kU * (24.0 * (std::abs(double(f0[i])) + span * std::pow(m, 5.0)) +
                 5.0 * span * std::pow(m, 4.0) * dcos);
  }
  return b;
}

// schlick_ggx_g1: r+1 1 u, k 3 u, 1-k 4 u, x(1-k) 5 u, + k 6 u, quotient 6 u + division: 18 u
// both sides, plus dx/x for an absolute difference dx (in u) in n.x.
double g1_rel_bound_u(float n_dot_x, double dx) {
  return 6 + kGlDiv + 6 + kCpuDiv + (n_dot_x > 0.0f ? dx / double(n_dot_x) : 0.0);
}

// ---- the cases --------------------------------------------------------------------------------

ElementCase constants_case() {
  ElementCase c{"constants", "u", 2, "", nullptr, {uvec4(0u)}};
  c.glsl =
      "put(0u, vec4(SH_PI, SH_INV_PI, MIN_ROUGHNESS, MIN_SPECULAR_APERTURE));\n"
      "put(1u, vec4(FIXED_POINT_SCALE, FIXED_POINT_INV_SCALE, FIXED_POINT_MAX,\n"
      "             float(LIGHT_MODEL_GLTF + 2 * LIGHT_MODEL_SEED + 4 * MAX_DIFFUSE_CONES)));";
  c.cpu = [](const uvec4*) {
    return std::vector<ExpectedSlot>{
        exact(vec4(sh::SH_PI, sh::SH_INV_PI, sh::MIN_ROUGHNESS, sh::MIN_SPECULAR_APERTURE)),
        exact(vec4(
            sh::FIXED_POINT_SCALE, sh::FIXED_POINT_INV_SCALE, sh::FIXED_POINT_MAX,
            float(sh::LIGHT_MODEL_GLTF + 2 * sh::LIGHT_MODEL_SEED + 4 * sh::MAX_DIFFUSE_CONES)))};
  };
  return c;
}

ElementCase hash_case() {
  ElementCase c{"pcg_hash, hash_combine, hash_to_unit, particle_random", "u", 2, "", nullptr, {}};
  const auto keys = hash_keys();
  for (size_t i = 0; i < keys.size(); ++i)
    c.inputs.push_back(uvec4(keys[i], keys[(i * 31 + 7) % keys.size()], 0u, 0u));
  c.glsl =
      "uvec4 a = uin(0u);\n"
      "putu(0u, uvec4(pcg_hash(a.x), hash_combine(a.x, a.y), hash_combine(a.y, a.x), 0u));\n"
      "put(1u, vec4(hash_to_unit(a.x), hash_to_unit(pcg_hash(a.x)), particle_random(a.x, a.y), "
      "0.0f));";
  c.cpu = [](const uvec4* in) {
    const uvec4 a = in[0];
    return std::vector<ExpectedSlot>{
        exact_u(
            uvec4(sh::pcg_hash(a.x), sh::hash_combine(a.x, a.y), sh::hash_combine(a.y, a.x), 0u)),
        exact(vec4(sh::hash_to_unit(a.x), sh::hash_to_unit(sh::pcg_hash(a.x)),
                   sh::particle_random(a.x, a.y), 0.0f))};
  };
  return c;
}

ElementCase fixed_point_case() {
  ElementCase c{"fixed_point_encode, fixed_point_resolve", "fu", 1, "", nullptr, {}};
  const std::vector<float> v = {-1.0f,          -0.0f,          0.0f,    1e-30f,  3.0517578e-05f,
                                6.1035156e-05f, 9.1552734e-05f, 0.25f,   0.999f,  1.0f,
                                3.14159f,       1023.99994f,    1024.0f, 1025.0f, 1e30f};
  const std::vector<uint32_t> counts = {0u, 1u, 2u, 3u, 7u, 255u, 256u, 65537u};
  const auto keys = hash_keys();
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t j = 0; j < counts.size(); ++j)
      for (size_t k = 0; k < 3; ++k)
        c.inputs.insert(c.inputs.end(),
                        {words(vec4(v[i], v[(i + 5) % v.size()], 0, 0)),
                         uvec4(keys[((i * 8 + j) * 3 + k) % keys.size()], counts[j], 0u, 0u)});
  c.glsl =
      "vec4 f = fin(0u); uvec4 q = uin(1u);\n"
      "putu(0u, uvec4(fixed_point_encode(f.x), fixed_point_encode(f.y),\n"
      "               floatBitsToUint(fixed_point_resolve(q.x, q.y)), "
      "floatBitsToUint(fixed_point_resolve(q.y, q.x))));";
  c.cpu = [](const uvec4* in) {
    const vec4 f = floats(in[0]);
    const uvec4 q = in[1];
    return std::vector<ExpectedSlot>{
        exact_u(uvec4(sh::fixed_point_encode(f.x), sh::fixed_point_encode(f.y),
                      words(vec4(sh::fixed_point_resolve(q.x, q.y))).x,
                      words(vec4(sh::fixed_point_resolve(q.y, q.x))).x))};
  };
  return c;
}

ElementCase ggx_case() {
  ElementCase c{"ggx_distribution", "ff", 1, "", nullptr, {}};
  const auto ns = normals();
  for (size_t i = 0; i < ns.size(); i += 2)
    for (double th : kThetas)
      for (float r : kRoughness)
        c.inputs.insert(c.inputs.end(), {words(vec4(ns[i], r)),
                                         words(vec4(around(ns[i], th, 0.7 * double(i)), 0))});
  c.glsl =
      "vec4 a = fin(0u), b = fin(1u);\nput(0u, vec4(ggx_distribution(a.xyz, b.xyz, a.w), 0.0f, "
      "0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), b = floats(in[1]);
    const float d = sh::ggx_distribution(vec3(a), vec3(b), a.w);
    return std::vector<ExpectedSlot>{
        within(vec4(d, 0, 0, 0),
               {kU * std::abs(double(d)) * ggx_rel_bound_u(vec3(a), vec3(b), a.w, 0.0), 0, 0, 0})};
  };
  return c;
}

ElementCase g1_case() {
  ElementCase c{"schlick_ggx_g1", "f", 1, "", nullptr, {}};
  const std::vector<float> xs = {0.0f, 1e-7f, 1e-5f,   1e-3f, 0.01f,  0.1f,
                                 0.3f, 0.5f,  0.7071f, 0.9f,  0.999f, 1.0f};
  for (float x : xs)
    for (float r : kRoughness) c.inputs.push_back(words(vec4(x, r, 0, 0)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(schlick_ggx_g1(a.x, a.y), 0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    const float g = sh::schlick_ggx_g1(a.x, a.y);
    return std::vector<ExpectedSlot>{
        within(vec4(g, 0, 0, 0), {kU * std::abs(double(g)) * g1_rel_bound_u(a.x, 0.0), 0, 0, 0})};
  };
  return c;
}

ElementCase fresnel_case() {
  ElementCase c{"fresnel_schlick", "ff", 1, "", nullptr, {}};
  const std::vector<float> cs = {-0.5f, 0.0f,  1e-6f, 1e-3f,   0.05f, 0.2f,
                                 0.5f,  0.75f, 0.99f, 0.9999f, 1.0f,  1.5f};
  const std::vector<vec4> f0s = {{0.04f, 0.04f, 0.04f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f},
                                 {0.95f, 0.64f, 0.54f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f},
                                 {0.02f, 0.03f, 0.0f, 0.5f},  {0.5f, 0.9f, 0.1f, 0.0f}};
  for (float ct : cs)
    for (const vec4& f : f0s) c.inputs.insert(c.inputs.end(), {words(f), words(vec4(ct, 0, 0, 0))});
  c.glsl = "vec4 f = fin(0u), a = fin(1u);\nput(0u, vec4(fresnel_schlick(f.xyz, f.w, a.x), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 f = floats(in[0]), a = floats(in[1]);
    const vec3 r = sh::fresnel_schlick(vec3(f), f.w, a.x);
    return std::vector<ExpectedSlot>{
        within(vec4(r, 0), glm::dvec4(fresnel_bound(vec3(f), f.w, a.x, 0.0), 0))};
  };
  return c;
}

ElementCase surface_pbr_case() {
  ElementCase c{"surface_pbr", "fff", 3, "", nullptr, {}};
  const std::vector<vec3> albedo = {
      {0, 0, 0}, {1, 1, 1}, {0.8f, 0.1f, 0.05f}, {0.18f, 0.18f, 0.18f}};
  const std::vector<float> metal = {-0.5f, 0.0f, 0.3f, 1.0f, 2.0f},
                           rough = {-1.0f, 0.0f, 0.02f, 0.5f, 1.0f, 3.0f};
  const std::vector<vec4> spec = {
      {1, 1, 1, 1}, {0, 1, 1, 1}, {0.5f, 2.0f, 30.0f, 0.7f}, {1, 0.5f, 0.25f, 0.0f}};
  for (const vec3& a : albedo)
    for (float m : metal)
      for (float r : rough)
        for (const vec4& s : spec)
          c.inputs.insert(c.inputs.end(), {words(vec4(a, m)), words(vec4(r, 0, 0, 0)), words(s)});
  c.glsl =
      "vec4 a = fin(0u), r = fin(1u), s = fin(2u);\n"
      "SurfacePbr p = surface_pbr(a.xyz, a.w, r.x, s.w, s.xyz);\n"
      "put(0u, vec4(p.albedo, p.metallic)); put(1u, vec4(p.f0, p.roughness)); put(2u, vec4(p.f90, "
      "0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), r = floats(in[1]), s = floats(in[2]);
    const sh::SurfacePbr p = sh::surface_pbr(vec3(a), a.w, r.x, s.w, vec3(s));
    // clamps exact; dielectric f0 = min(0.04 c, 1) * s: 2 u; mix(x, y, m) as x(1-m) + y m or as
    // x + m(y - x) (drivers lower it either way): 3 u of |x| + |y| on top of x's own error.
    const vec3 d = glm::min(vec3(0.04f) * vec3(s), vec3(1.0f)) * s.w;
    glm::dvec4 f0b(0.0);
    for (int i = 0; i < 3; ++i)
      f0b[i] =
          kU * 2.0 *
          (2.0 * std::abs(double(d[i])) + 3.0 * (std::abs(double(d[i])) + std::abs(double(a[i]))));
    const double f90b = kU * 2.0 * 3.0 * (std::abs(double(s.w)) + 1.0);
    return std::vector<ExpectedSlot>{exact(vec4(p.albedo, p.metallic)),
                                     within(vec4(p.f0, p.roughness), f0b),
                                     within(vec4(p.f90, 0, 0, 0), {f90b, 0, 0, 0})};
  };
  return c;
}

ElementCase diffuse_weight_case() {
  ElementCase c{"diffuse_weight", "ff", 1, "", nullptr, {}};
  const std::vector<float> metal = {0.0f, 0.25f, 0.5f, 1.0f};
  const std::vector<vec3> fs = {{0, 0, 0}, {1, 1, 1}, {0.04f, 0.5f, 0.9999f}, {0.3f, 0.7f, 1e-7f}};
  for (float m : metal)
    for (const vec3& f : fs)
      c.inputs.insert(c.inputs.end(), {words(vec4(0.5f, 0.5f, 0.5f, m)), words(vec4(f, 0))});
  c.glsl =
      "vec4 a = fin(0u), f = fin(1u);\n"
      "SurfacePbr s = SurfacePbr(a.xyz, a.w, 0.5f, vec3(0.04f), 1.0f);\n"
      "put(0u, vec4(diffuse_weight(s, f.xyz), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), f = floats(in[1]);
    const sh::SurfacePbr s{vec3(a), a.w, 0.5f, vec3(0.04f), 1.0f};
    const vec3 w = sh::diffuse_weight(s, vec3(f));
    // (1 - F) 1 u, (1 - metallic) 1 u, product 1 u: 3 u per side.
    return std::vector<ExpectedSlot>{
        within(vec4(w, 0), glm::dvec4(kU * 6.0 * glm::abs(glm::dvec3(w)), 0))};
  };
  return c;
}

// Shared by cook_torrance_lobes and cook_torrance: the lobes' bound from the pieces' bounds, with
// h = normalize(v + l) differing by kNormalizeNorm (+ v + l's 1 u) and n.l, n.v, h.v by 3 u per
// side.
struct LobeBounds {
  glm::dvec3 diffuse, specular;
};
// `nv_mode`: the view cosine's mode (sh::view_cosine: |.| and max are exact, so n.v keeps its 3 u
// per side under every mode).
LobeBounds lobe_bounds(const sh::SurfacePbr& s, const vec3& n, const vec3& v, const vec3& l, int nv_mode = sh::NV_ZERO) {
  const float nl = glm::dot(n, l), nv = sh::view_cosine(glm::dot(n, v), nv_mode);
  if (nl <= 0.0f || nv <= 0.0f) return {glm::dvec3(0.0), glm::dvec3(0.0)};
  const vec3 h = glm::normalize(v + l);
  const double eps_h = kNormalizeNorm + 2.0;
  const float hv = std::max(glm::dot(h, v), 0.0f);
  const glm::dvec3 fb = fresnel_bound(s.f0, s.f90, hv, 6.0 + eps_h);
  const vec3 f = sh::fresnel_schlick(s.f0, s.f90, hv);
  const double d = sh::ggx_distribution(n, h, s.roughness);
  const double g =
      double(sh::schlick_ggx_g1(nl, s.roughness)) * double(sh::schlick_ggx_g1(nv, s.roughness));
  const double q = d * g / (4.0 * double(nl) * double(nv));
  // q = D G / (4 n.l n.v): D, both G1, the denominator (n.l, n.v again + 2 products) and the
  // division, then the product with F (1 u per side).
  const double q_rel = ggx_rel_bound_u(n, h, s.roughness, eps_h) + g1_rel_bound_u(nl, 6.0) +
                       g1_rel_bound_u(nv, 6.0) + 6.0 / double(nl) + 6.0 / double(nv) + 4.0 +
                       kGlDiv + kCpuDiv + 4.0;
  LobeBounds b;
  for (int i = 0; i < 3; ++i) {
    b.specular[i] = std::abs(double(f[i])) * q * q_rel * kU + q * fb[i];
    const double kd_a = (1.0 - double(s.metallic)) * double(s.albedo[i]) * double(sh::SH_INV_PI);
    // (1 - F) (1 - metallic) albedo / pi: 4 products and differences of 1 u, per side.
    b.diffuse[i] = kd_a * (fb[i] + 8.0 * kU * std::abs(1.0 - double(f[i])));
  }
  return b;
}

void brdf_inputs(ElementCase& c) {
  const auto ns = normals();
  const std::vector<vec4> surf_a = {
      {0.8f, 0.6f, 0.2f, 0.0f}, {0.95f, 0.64f, 0.54f, 1.0f}, {0.5f, 0.5f, 0.5f, 0.5f}};
  const std::vector<double> th = {1e-4, 0.3, 1.0, 1.5, 1.5707, 1.5707963};  // grazing near pi/2
  for (size_t i = 0; i < ns.size(); i += 5)
    for (size_t a = 0; a < surf_a.size(); ++a)
      for (float r : {sh::MIN_ROUGHNESS, 0.1f, 0.5f, 1.0f})
        for (double tv : th)
          for (double tl : th) {
            const vec3 n = ns[i], v = around(n, tv, 0.3 * double(i)),
                       l = around(n, tl, 0.3 * double(i) + 2.5 + tv);
            // n.l = 0 is the BRDF's cut-off (both lobes 0 below it): a dot within GL's 3 u of it
            // could fall on either side, so such grid points are left out (the exact zeros of
            // axis-aligned n and l stay in: dot is exact there).
            const double dl = glm::dot(glm::dvec3(n), glm::dvec3(l)),
                         dv = glm::dot(glm::dvec3(n), glm::dvec3(v));
            if ((std::abs(dl) < 1e-5 && dl != 0.0) || (std::abs(dv) < 1e-5 && dv != 0.0)) continue;
            const sh::SurfacePbr s =
                sh::surface_pbr(vec3(surf_a[a]), surf_a[a].w, r, a == 2 ? 0.5f : 1.0f, vec3(1.0f));
            c.inputs.insert(c.inputs.end(),
                            {words(vec4(s.albedo, s.metallic)), words(vec4(s.f0, s.roughness)),
                             words(vec4(s.f90, 0, 0, 0)), words(vec4(n, 0)), words(vec4(v, 0)),
                             words(vec4(l, 0))});
          }
  // Exact zeros: l in the tangent plane of an axis-aligned normal.
  const sh::SurfacePbr s = sh::surface_pbr(vec3(0.5f), 0.0f, 0.5f, 1.0f, vec3(1.0f));
  c.inputs.insert(c.inputs.end(),
                  {words(vec4(s.albedo, s.metallic)), words(vec4(s.f0, s.roughness)),
                   words(vec4(s.f90, 0, 0, 0)), words(vec4(0, 0, 1, 0)),
                   words(vec4(0, 0.6f, 0.8f, 0)), words(vec4(1, 0, 0, 0))});
}

const char* kSurfaceFromInputs =
    "vec4 a = fin(0u), b = fin(1u), e = fin(2u);\n"
    "SurfacePbr s = SurfacePbr(a.xyz, a.w, b.w, b.xyz, e.x);\n"
    "vec3 n = fin(3u).xyz, v = fin(4u).xyz, l = fin(5u).xyz;\n";

sh::SurfacePbr surface_from_inputs(const uvec4* in) {
  const vec4 a = floats(in[0]), b = floats(in[1]), e = floats(in[2]);
  return sh::SurfacePbr{vec3(a), a.w, b.w, vec3(b), e.x};
}

ElementCase lobes_case() {
  ElementCase c{"cook_torrance_lobes", "ffffff", 2, "", nullptr, {}};
  brdf_inputs(c);
  c.glsl = std::string(kSurfaceFromInputs) +
           "BrdfLobes o = cook_torrance_lobes(s, n, v, l);\nput(0u, vec4(o.diffuse, 0.0f)); "
           "put(1u, vec4(o.specular, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::SurfacePbr s = surface_from_inputs(in);
    const vec3 n(floats(in[3])), v(floats(in[4])), l(floats(in[5]));
    const sh::BrdfLobes o = sh::cook_torrance_lobes(s, n, v, l);
    const LobeBounds b = lobe_bounds(s, n, v, l);
    return std::vector<ExpectedSlot>{within(vec4(o.diffuse, 0), glm::dvec4(b.diffuse, 0)),
                                     within(vec4(o.specular, 0), glm::dvec4(b.specular, 0))};
  };
  return c;
}

ElementCase cook_torrance_case() {
  ElementCase c{"cook_torrance", "ffffff", 1, "", nullptr, {}};
  brdf_inputs(c);
  c.glsl = std::string(kSurfaceFromInputs) + "put(0u, vec4(cook_torrance(s, n, v, l), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::SurfacePbr s = surface_from_inputs(in);
    const vec3 n(floats(in[3])), v(floats(in[4])), l(floats(in[5]));
    const vec3 f = sh::cook_torrance(s, n, v, l);
    const LobeBounds b = lobe_bounds(s, n, v, l);
    return std::vector<ExpectedSlot>{within(
        vec4(f, 0), glm::dvec4(b.diffuse + b.specular + 2.0 * kU * glm::abs(glm::dvec3(f)), 0))};
  };
  return c;
}

// The view cosine's modes (issue 39): exact operations, so bit-exact on both sides.
ElementCase view_cosine_case() {
  ElementCase c{"view_cosine", "f", 1, "", nullptr, {}};
  // No -0: llvmpipe's abs gives +0 where the C++ comparison keeps -0, and the BRDF takes either
  // as n.v <= 0 (a zero's sign is no value GLSL 4.50 §4.7.1 pins).
  for (float x : {-1.0f, -0.5f, -1e-4f, -1e-7f, 0.0f, 1e-7f, 5e-5f, 1e-4f, 2e-4f, 0.3f, 1.0f})
    for (int mode : {sh::NV_ZERO, sh::NV_ABS, sh::NV_CLAMP}) c.inputs.push_back(words(vec4(x, float(mode), 0, 0)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(view_cosine(a.x, int(a.y)), 0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    return std::vector<ExpectedSlot>{exact(vec4(sh::view_cosine(a.x, int(a.y)), 0, 0, 0))};
  };
  return c;
}

// The BRDF grid under abs and clamp, with each view direction also mirrored below the surface
// (v - 2 (n.v) n): the silhouette pixels whose n.v < 0 the modes are about.
void brdf_inputs_nv(ElementCase& c) {
  ElementCase grid;
  brdf_inputs(grid);
  for (size_t p = 0; p + 6 <= grid.inputs.size(); p += 6)
    for (bool below : {false, true})
      for (int mode : {sh::NV_ABS, sh::NV_CLAMP}) {
        std::vector<uvec4> point(grid.inputs.begin() + long(p), grid.inputs.begin() + long(p + 6));
        if (below) {
          const vec3 n(floats(point[3])), v(floats(point[4])), l(floats(point[5]));
          const vec3 m = v - 2.0f * glm::dot(n, v) * n;
          const double dv = glm::dot(glm::dvec3(n), glm::dvec3(m));
          // As brdf_inputs: a dot within GL's 3 u of the cut-off, or v + l too short for
          // normalize's relative bound, is left out.
          if ((std::abs(dv) < 1e-5 && dv != 0.0) || glm::length(m + l) < 1e-3f) continue;
          point[4] = words(vec4(m, 0));
        }
        c.inputs.insert(c.inputs.end(), point.begin(), point.end());
        c.inputs.push_back(words(vec4(float(mode), 0, 0, 0)));
      }
}

ElementCase lobes_nv_case() {
  ElementCase c{"cook_torrance_lobes_nv", "fffffff", 2, "", nullptr, {}};
  brdf_inputs_nv(c);
  c.glsl = std::string(kSurfaceFromInputs) +
           "BrdfLobes o = cook_torrance_lobes_nv(s, n, v, l, int(fin(6u).x));\nput(0u, vec4(o.diffuse, 0.0f)); "
           "put(1u, vec4(o.specular, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::SurfacePbr s = surface_from_inputs(in);
    const vec3 n(floats(in[3])), v(floats(in[4])), l(floats(in[5]));
    const int mode = int(floats(in[6]).x);
    const sh::BrdfLobes o = sh::cook_torrance_lobes_nv(s, n, v, l, mode);
    const LobeBounds b = lobe_bounds(s, n, v, l, mode);
    return std::vector<ExpectedSlot>{within(vec4(o.diffuse, 0), glm::dvec4(b.diffuse, 0)),
                                     within(vec4(o.specular, 0), glm::dvec4(b.specular, 0))};
  };
  return c;
}

ElementCase cook_torrance_nv_case() {
  ElementCase c{"cook_torrance_nv", "fffffff", 1, "", nullptr, {}};
  brdf_inputs_nv(c);
  c.glsl = std::string(kSurfaceFromInputs) + "put(0u, vec4(cook_torrance_nv(s, n, v, l, int(fin(6u).x)), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::SurfacePbr s = surface_from_inputs(in);
    const vec3 n(floats(in[3])), v(floats(in[4])), l(floats(in[5]));
    const int mode = int(floats(in[6]).x);
    const vec3 f = sh::cook_torrance_nv(s, n, v, l, mode);
    const LobeBounds b = lobe_bounds(s, n, v, l, mode);
    return std::vector<ExpectedSlot>{within(
        vec4(f, 0), glm::dvec4(b.diffuse + b.specular + 2.0 * kU * glm::abs(glm::dvec3(f)), 0))};
  };
  return c;
}

// Spot grid: cos of the angle to the axis across and outside the cone, distances from 0 to
// beyond the range, cones from a hard edge (inner == outer) to a wide soft one.
std::vector<vec4> spot_cones() {
  return {{0.9f, 0.8f, 0, 0},
          {0.99f, 0.5f, 0, 0},
          {0.7f, 0.7f, 0, 0},
          {1.0f, 0.0f, 0, 0},
          {0.95f, 0.9495f, 0, 0}};
}
const std::vector<float> kCosAxis = {-1.0f, 0.0f, 0.5f,    0.7f,  0.79f, 0.8f, 0.81f,
                                     0.85f, 0.9f, 0.9495f, 0.95f, 0.99f, 1.0f};

// spot_cone_gltf: ci - co 1 u, 1/x + division, (ca - co) 1 u, product 1 u, square: 2 x (GL 8 u,
// C++ 4 u) + 1 u per side = 26 u of the result.
constexpr double kSpotConeU = 2.0 * (3.0 + kGlDiv) + 1.0 + 2.0 * (3.0 + kCpuDiv) + 1.0;

ElementCase spot_cone_case() {
  ElementCase c{"spot_cone_gltf", "f", 1, "", nullptr, {}};
  for (const vec4& cone : spot_cones())
    for (float ca : kCosAxis) c.inputs.push_back(words(vec4(ca, cone.x, cone.y, 0)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(spot_cone_gltf(a.x, a.y, a.z), 0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    const float r = sh::spot_cone_gltf(a.x, a.y, a.z);
    return std::vector<ExpectedSlot>{
        within(vec4(r, 0, 0, 0), {kU * kSpotConeU * double(r), 0, 0, 0})};
  };
  return c;
}

// Hard spots (docs/compare.md, "Hard spots"): spot_is_hard and spot_step are comparisons of the
// same floats on both sides, so exact; the grid's cone (0.7, 0.7) and cos 0.7 hit the edge itself.
ElementCase hard_spot_case() {
  ElementCase c{"spot_is_hard", "f", 1, "", nullptr, {}};
  for (const vec4& cone : spot_cones())
    for (float ca : kCosAxis) c.inputs.push_back(words(vec4(ca, cone.x, cone.y, 0)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(spot_is_hard(a.y, a.z) ? 1.0f : 0.0f, spot_step(a.x, a.z), 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    return std::vector<ExpectedSlot>{exact(vec4(sh::spot_is_hard(a.y, a.z) ? 1.0f : 0.0f, sh::spot_step(a.x, a.z), 0, 0))};
  };
  return c;
}

// range_window: r = d/range (division), r^4 = 4 x r's + 3 u, then 1 - r^4 (1 u of the result).
double range_window_bound(float dist, float range) {
  if (range <= 0.0f) return 0.0;
  const double r4 = std::pow(double(dist) / double(range), 4.0);
  const double w = std::clamp(1.0 - r4, 0.0, 1.0);
  return kU * ((4.0 * kGlDiv + 3.0 + 4.0 * kCpuDiv + 3.0) * r4 + 2.0 * w);
}

ElementCase range_window_case() {
  ElementCase c{"range_window", "f", 1, "", nullptr, {}};
  for (float range : {-1.0f, 0.0f, 1.0f, 7.5f})
    for (float d : {0.0f, 1e-3f, 0.5f, 0.999f, 1.0f, 2.0f, 7.4999f, 7.5f, 100.0f})
      c.inputs.push_back(words(vec4(d, range, 0, 0)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(range_window(a.x, a.y), 0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    const float w = sh::range_window(a.x, a.y);
    return std::vector<ExpectedSlot>{
        within(vec4(w, 0, 0, 0), {range_window_bound(a.x, a.y), 0, 0, 0})};
  };
  return c;
}

// step_corrected_opacity / step_corrected_sample: 1 - pow(1 - a, r). GLSL 4.50 §4.7.1 defines
// pow's precision as that of exp2(r * log2(x)): log2 within 2^-21 absolute on [0.5, 2] and 3 ulp
// (6 u) elsewhere, the product 1 u, exp2 (3 + 2|z|) ulp = (6 + 4|z|) u relative; an absolute error
// E in z = r log2(x) becomes ln2 E relative in exp2. glibc's powf is within 1 ulp (2 u). 1 - a and
// the clamp are exact or correctly rounded alike on both sides; the final 1 - p rounds once (1 u
// of the result, each side). The sample's rgb is rgb * (a'/a): a'/a carries a''s relative bound,
// the division 5 u (GL) + 1 u (C++), the product 1 u each side, so |d rgb'| <= |rgb|/a |d a'| +
// 8 u |rgb'|; a = 0 multiplies by r (1 u each side).
double step_opacity_bound(float a, float r) {
  const double x = std::clamp(1.0 - double(a), 0.0, 1.0);
  if (x == 0.0) return 0.0;  // pow(0, r > 0) = 0 on both sides (exp2(-inf))
  const double l = std::log2(x), z = double(r) * l, p = std::exp2(z);
  const double log_err = x >= 0.5 ? 8.0 * kU : 6.0 * kU * std::abs(l);
  const double e_z = double(r) * log_err + kU * std::abs(z);
  const double pow_rel = std::log(2.0) * e_z + (6.0 + 4.0 * std::abs(z)) * kU + kCpuLibmU * kU;
  return p * pow_rel + 2.0 * kU * std::abs(1.0 - p);
}

ElementCase step_correction_case() {
  ElementCase c{"step_corrected_opacity, step_corrected_sample", "ff", 2, "", nullptr, {}};
  for (float a : {0.0f, 1e-6f, 1e-3f, 0.01f, 0.1f, 0.25f, 0.5f, 0.75f, 0.9f, 0.99f, 0.999f, 1.0f})
    for (float r : {0.01f, 0.125f, 0.25f, 0.5f, 0.7f, 1.0f, 2.0f, 4.0f})
      c.inputs.insert(c.inputs.end(), {words(vec4(a, r, 0, 0)), words(vec4(0.3f, 1.7f, 0.0f, 0.0f) * a)});
  c.glsl =
      "vec4 a = fin(0u), s = fin(1u);\nput(0u, vec4(step_corrected_opacity(a.x, a.y), 0.0f, 0.0f, 0.0f));\n"
      "put(1u, step_corrected_sample(vec4(s.xyz, a.x), a.y));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), s = floats(in[1]);
    const float o = sh::step_corrected_opacity(a.x, a.y);
    const vec4 cs = sh::step_corrected_sample(vec4(vec3(s), a.x), a.y);
    const double ob = step_opacity_bound(a.x, a.y);
    // |d rgb'| <= |rgb| / a * |d a'| + |rgb'| * 8 u (a' may be 0 on one side and tiny on the other).
    glm::dvec4 sb(ob);
    for (int k = 0; k < 3; ++k)
      sb[k] = a.x > 0.0f ? std::abs(double(s[k])) / double(a.x) * ob + std::abs(double(cs[k])) * 8.0 * kU
                         : std::abs(double(cs[k])) * 2.0 * kU;
    return std::vector<ExpectedSlot>{within(vec4(o, 0, 0, 0), {ob, 0, 0, 0}), within(cs, sb)};
  };
  return c;
}

ElementCase spot_irradiance_case() {
  ElementCase c{"spot_irradiance", "ff", 1, "", nullptr, {}};
  for (int model : {sh::LIGHT_MODEL_GLTF, sh::LIGHT_MODEL_SEED})
    for (const vec4& cone : spot_cones())
      for (float ca : kCosAxis)
        // GLSL leaves smoothstep undefined for edge0 >= edge1 (§8.3): the seed model only with
        // a soft edge.
        if (model == sh::LIGHT_MODEL_GLTF || cone.x > cone.y)
          for (float d : {0.0f, 1e-5f, 0.5f, 3.0f, 9.9f})
            for (float range : {0.0f, 10.0f})
              c.inputs.insert(
                  c.inputs.end(),
                  {words(vec4(1.0f, 0.9f, 0.3f, 40.0f)), words(vec4(d, ca, cone.x, cone.y)),
                   uvec4(uint32_t(model), words(vec4(range)).x, 0u, 0u)});
  c.in_kinds = "ffu";
  c.glsl =
      "vec4 a = fin(0u), b = fin(1u); uvec4 m = uin(2u);\n"
      "put(0u, vec4(spot_irradiance(int(m.x), a.xyz, a.w, b.x, b.y, b.z, b.w, "
      "uintBitsToFloat(m.y)), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), b = floats(in[1]);
    const int model = int(in[2].x);
    const float range = as_float(in[2].y);
    const vec3 e = sh::spot_irradiance(model, vec3(a), a.w, b.x, b.y, b.z, b.w, range);
    glm::dvec3 bound;
    if (model == sh::LIGHT_MODEL_SEED) {
      // smoothstep(e0, e1, x) = t^2 (3 - 2t), t = clamp((x - e0)/(e1 - e0)): t GL 7 u / C++ 3 u,
      // t^2 (3 - 2t) 4 x t's + 3 u: GL 31 u, C++ 15 u; color*I, *ss, 1 + d, division: GL 8 u,
      // C++ 4 u. 58 u of the result.
      bound = kU * 58.0 * glm::abs(glm::dvec3(e));
    } else {
      // cone 26 u; color*I, *cone, *window 3 u per side; d*d 1 u + division per side; plus the
      // window's absolute bound times the rest.
      const double rest = double(a.w) * double(sh::spot_cone_gltf(b.y, b.z, b.w)) /
                          std::max(double(b.x) * double(b.x), 1e-8);
      const double rel = kSpotConeU + 6.0 + 2.0 + kGlDiv + kCpuDiv;
      for (int i = 0; i < 3; ++i)
        bound[i] = kU * rel * std::abs(double(e[i])) +
                   double(a[i]) * rest * range_window_bound(b.x, range);
    }
    return std::vector<ExpectedSlot>{within(vec4(e, 0), glm::dvec4(bound, 0))};
  };
  return c;
}

// directional_irradiance: color * lux, 1 u per side.
ElementCase directional_irradiance_case() {
  ElementCase c{"directional_irradiance", "f", 1, "", nullptr, {}};
  for (float lux : {0.0f, 1e-3f, 1.0f, 8.0f, 1e5f}) c.inputs.push_back(words(vec4(1.0f, 0.9f, 0.3f, lux)));
  c.glsl = "vec4 a = fin(0u);\nput(0u, vec4(directional_irradiance(a.xyz, a.w), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    const vec3 e = sh::directional_irradiance(vec3(a), a.w);
    return std::vector<ExpectedSlot>{within(vec4(e, 0), glm::dvec4(kU * 2.0 * glm::abs(glm::dvec3(e)), 0))};
  };
  return c;
}

// point_irradiance. Seed: color*I 1 u, 1 + d 1 u, division: GL 7 u, C++ 3 u = 10 u relative.
// glTF: color*I, *window 2 u, d*d 1 u, division: GL 8 u, C++ 4 u = 12 u relative, plus the window's
// absolute bound times color*I/d^2.
glm::dvec3 point_irradiance_bound(int model, const vec3& color, float intensity, float d, float range,
                                  const vec3& e) {
  if (model == sh::LIGHT_MODEL_SEED) return kU * 10.0 * glm::abs(glm::dvec3(e));
  const double rest = double(intensity) / std::max(double(d) * double(d), 1e-8);
  glm::dvec3 b;
  for (int i = 0; i < 3; ++i)
    b[i] = kU * (6.0 + kGlDiv + kCpuDiv) * std::abs(double(e[i])) + double(color[i]) * rest * range_window_bound(d, range);
  return b;
}

ElementCase point_irradiance_case() {
  ElementCase c{"point_irradiance", "ff", 1, "", nullptr, {}};
  for (int model : {sh::LIGHT_MODEL_GLTF, sh::LIGHT_MODEL_SEED})
    for (float d : {0.0f, 1e-5f, 0.5f, 3.0f, 9.9f, 10.0f, 30.0f})
      for (float range : {0.0f, 10.0f})
        c.inputs.insert(c.inputs.end(), {words(vec4(1.0f, 0.9f, 0.3f, 40.0f)),
                                         uvec4(uint32_t(model), words(vec4(d)).x, words(vec4(range)).x, 0u)});
  c.in_kinds = "fu";
  c.glsl =
      "vec4 a = fin(0u); uvec4 m = uin(1u);\n"
      "put(0u, vec4(point_irradiance(int(m.x), a.xyz, a.w, uintBitsToFloat(m.y), uintBitsToFloat(m.z)), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]);
    const int model = int(in[1].x);
    const float d = as_float(in[1].y), range = as_float(in[1].z);
    const vec3 e = sh::point_irradiance(model, vec3(a), a.w, d, range);
    return std::vector<ExpectedSlot>{within(vec4(e, 0), glm::dvec4(point_irradiance_bound(model, vec3(a), a.w, d, range, e), 0))};
  };
  return c;
}

// punctual_irradiance: the dispatch on the kind; each branch's bound (the spot's as in
// spot_irradiance_case, glTF model with a soft cone).
ElementCase punctual_irradiance_case() {
  ElementCase c{"punctual_irradiance", "ff", 1, "", nullptr, {}};
  for (int kind : {sh::LIGHT_KIND_SPOT, sh::LIGHT_KIND_POINT, sh::LIGHT_KIND_DIRECTIONAL})
    for (float ca : {0.0f, 0.85f, 0.95f})
      for (float d : {0.5f, 3.0f})
        c.inputs.insert(c.inputs.end(), {words(vec4(1.0f, 0.9f, 0.3f, 40.0f)), words(vec4(d, ca, 0.9f, 0.8f)),
                                         uvec4(uint32_t(kind), words(vec4(10.0f)).x, 0u, 0u)});
  c.in_kinds = "ffu";
  c.glsl =
      "vec4 a = fin(0u), b = fin(1u); uvec4 m = uin(2u);\n"
      "put(0u, vec4(punctual_irradiance(LIGHT_MODEL_GLTF, int(m.x), a.xyz, a.w, b.x, b.y, b.z, b.w, "
      "uintBitsToFloat(m.y)), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), b = floats(in[1]);
    const int kind = int(in[2].x);
    const float range = as_float(in[2].y);
    const vec3 e = sh::punctual_irradiance(sh::LIGHT_MODEL_GLTF, kind, vec3(a), a.w, b.x, b.y, b.z, b.w, range);
    glm::dvec3 bound;
    if (kind == sh::LIGHT_KIND_DIRECTIONAL) {
      bound = kU * 2.0 * glm::abs(glm::dvec3(e));
    } else if (kind == sh::LIGHT_KIND_POINT) {
      bound = point_irradiance_bound(sh::LIGHT_MODEL_GLTF, vec3(a), a.w, b.x, range, e);
    } else {
      const double rest = double(a.w) * double(sh::spot_cone_gltf(b.y, b.z, b.w)) / std::max(double(b.x) * double(b.x), 1e-8);
      for (int i = 0; i < 3; ++i)
        bound[i] = kU * (kSpotConeU + 6.0 + 2.0 + kGlDiv + kCpuDiv) * std::abs(double(e[i])) +
                   double(a[i]) * rest * range_window_bound(b.x, range);
    }
    return std::vector<ExpectedSlot>{within(vec4(e, 0), glm::dvec4(bound, 0))};
  };
  return c;
}

// to_light_direction. Directional: -normalize(direction), kNormalizeNorm in norm (16 u per unit
// component). Positional: the difference p_l - p has absolute error 1 u (|p_l| + |p|) per component
// and side; length = sqrt(dot) (dot 3 u, GL sqrt = 1/inversesqrt: 4 + 5 u; C++ 1 u, halved through
// the root) and the division (GL 5 u, C++ 1 u) are relative to the unit result: per component
// 2 u (|p_l| + |p|)_i / dist + (1.5 + 9 + 5) + (1.5 + 1 + 1) u. p = p_l gives (0, 0, 1) on both.
ElementCase to_light_direction_case() {
  ElementCase c{"to_light_direction", "ff", 1, "", nullptr, {}};
  const std::vector<vec3> points = {{0, 0, 0}, {1, 2, 3}, {-3.5f, 0.25f, 7}, {1e-3f, 0, 0}, {100, -50, 20}};
  for (int kind : {sh::LIGHT_KIND_POINT, sh::LIGHT_KIND_DIRECTIONAL})
    for (const vec3& lp : points)
      for (const vec3& p : points)
        c.inputs.insert(c.inputs.end(), {words(vec4(lp, float(kind))), words(vec4(p, 0.0f))});
  c.glsl =
      "vec4 a = fin(0u), b = fin(1u);\n"
      "put(0u, vec4(to_light_direction(int(a.w), a.xyz, normalize(vec3(0.3f, -1.0f, 0.2f)), b.xyz), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), b = floats(in[1]);
    const int kind = int(a.w);
    const vec3 dir = glm::normalize(vec3(0.3f, -1.0f, 0.2f));
    const vec3 l = sh::to_light_direction(kind, vec3(a), dir, vec3(b));
    glm::dvec4 bound(0.0);
    if (kind == sh::LIGHT_KIND_DIRECTIONAL) {
      // The GL side normalizes the direction twice (the argument, then inside): 2 x the norm bound.
      bound = glm::dvec4(glm::dvec3(2.0 * kNormalizeNorm * kU), 0.0);
    } else if (vec3(a) != vec3(b)) {
      const double dist = glm::length(glm::dvec3(vec3(a)) - glm::dvec3(vec3(b)));
      for (int i = 0; i < 3; ++i)
        bound[i] = kU * (2.0 * (std::abs(double(a[i])) + std::abs(double(b[i]))) / dist + 15.5 + 3.5);
    }
    return std::vector<ExpectedSlot>{within(vec4(l, 0), bound)};
  };
  return c;
}

// Cone blocks as stages/cone_sets.h builds them: the seed set (5 cones, 45 degrees), 1 cone,
// 9 at 60 degrees and the largest set; the weights are arbitrary distinct values.
std::vector<sh::DiffuseConeBlock> cone_blocks() {
  std::vector<sh::DiffuseConeBlock> b;
  const std::vector<std::pair<int, double>> sets = {
      {5, 45.0}, {1, 30.0}, {9, 60.0}, {sh::MAX_DIFFUSE_CONES, 80.0}};
  for (const auto& [count, tilt] : sets) {
    const double t = tilt * 3.14159265358979323846 / 180.0;
    const float step = count > 1 ? float(2.0 * 3.14159265358979323846 / (count - 1)) : 0.0f;
    b.push_back({vec4(float(std::sin(t)), float(std::cos(t)), step, float(count)),
                 vec4(0.25f, 0.1875f, 0, 0)});
  }
  return b;
}

ElementCase cone_direction_case() {
  ElementCase c{"diffuse_cone_direction", "ffu", 1, "", nullptr, {}};
  for (const auto& b : cone_blocks())
    for (float rot : {0.0f, 1e-6f, 0.5f, 1.5707964f, b.shape.z * 0.99999f})
      for (int i = 0; i < int(b.shape.w); ++i)
        c.inputs.insert(c.inputs.end(), {words(b.shape), words(b.weights),
                                         uvec4(uint32_t(i), words(vec4(rot)).x, 0u, 0u)});
  c.glsl =
      "DiffuseConeBlock b = DiffuseConeBlock(fin(0u), fin(1u)); uvec4 k = uin(2u);\n"
      "put(0u, vec4(diffuse_cone_direction(int(k.x), uintBitsToFloat(k.y), b), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::DiffuseConeBlock b{floats(in[0]), floats(in[1])};
    const int i = int(in[2].x);
    const float rot = as_float(in[2].y);
    const vec3 d = sh::diffuse_cone_direction(i, rot, b);
    glm::dvec4 bound(0.0);
    if (i > 0) {
      // phi = rot + (i-1) step: 2 u of |rot| + |(i-1) step| per side; s cos(phi), s sin(phi):
      // the sin/cos bounds, phi's difference, 1 u per side for the product.
      const double phi_err = 4.0 * kU * (std::abs(double(rot)) + double(i - 1) * double(b.shape.z));
      const double s = std::abs(double(b.shape.x));
      for (int k = 0; k < 2; ++k)
        bound[k] =
            s * (kGlSinCosAbs + kCpuLibmU * kU + phi_err) + 2.0 * kU * std::abs(double(d[k]));
    }
    return std::vector<ExpectedSlot>{within(vec4(d, 0), bound)};
  };
  return c;
}

ElementCase cone_block_case() {
  ElementCase c{
      "diffuse_cone_count, diffuse_cone_weight, diffuse_cone_rotation", "ffu", 1, "", nullptr, {}};
  const auto keys = hash_keys();
  size_t n = 0;
  for (const auto& b : cone_blocks())
    for (int i = 0; i < 3; ++i)
      for (int p = 0; p < 20; ++p, ++n)
        c.inputs.insert(c.inputs.end(), {words(b.shape), words(b.weights),
                                         uvec4(uint32_t(i), keys[n % keys.size()],
                                               keys[(n * 7 + 3) % keys.size()], uint32_t(p))});
  c.glsl =
      "DiffuseConeBlock b = DiffuseConeBlock(fin(0u), fin(1u)); uvec4 k = uin(2u);\n"
      "put(0u, vec4(float(diffuse_cone_count(b)), diffuse_cone_weight(int(k.x), b),\n"
      "             diffuse_cone_rotation(k.y, k.z, k.w, b), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::DiffuseConeBlock b{floats(in[0]), floats(in[1])};
    const uvec4 k = in[2];
    // Rotation: exact hash, exact hash_to_unit, one correctly rounded product: bit-exact.
    return std::vector<ExpectedSlot>{
        exact(vec4(float(sh::diffuse_cone_count(b)), sh::diffuse_cone_weight(int(k.x), b),
                   sh::diffuse_cone_rotation(k.y, k.z, k.w, b), 0.0f))};
  };
  return c;
}

ElementCase aperture_case() {
  ElementCase c{"specular_cone_aperture", "f", 1, "", nullptr, {}};
  for (float r : kRoughness) c.inputs.push_back(words(vec4(r, 0, 0, 0)));
  for (int i = 0; i <= 40; ++i) c.inputs.push_back(words(vec4(float(i) / 40.0f, 0, 0, 0)));
  c.glsl = "put(0u, vec4(specular_cone_aperture(fin(0u).x), 0.0f, 0.0f, 0.0f));";
  c.cpu = [](const uvec4* in) {
    const float r = floats(in[0]).x;
    const float a = sh::specular_cone_aperture(r);
    // a = r^2 (1 u; atan's condition a/((1+a^2) atan a) <= 1 carries it unchanged), atan GL
    // 8192 u / C++ 2 u, 2x exact; the clamp is continuous.
    return std::vector<ExpectedSlot>{
        within(vec4(a, 0, 0, 0), {kU * (kGlAtanU + kCpuLibmU + 2.0) * double(a), 0, 0, 0})};
  };
  return c;
}

ElementCase frame_case() {
  ElementCase c{"frame_from_normal", "f", 2, "", nullptr, {}};
  for (const vec3& n : normals()) c.inputs.push_back(words(vec4(n, 0)));
  c.glsl =
      "Frame f = frame_from_normal(fin(0u).xyz);\nput(0u, vec4(f.t, f.n.x)); put(1u, vec4(f.b, "
      "f.n.y + f.n.z));";
  c.cpu = [](const uvec4* in) {
    const vec3 n(floats(in[0]));
    const sh::Frame f = sh::frame_from_normal(n);
    // a = -1/(s + z) (s + z >= 1: 1 u, then the division), b = x y a (2 u more), s x^2 a (2 u
    // more), 1 + s x^2 a and s + y^2 a add 1 u of their result per side. |a| <= 1.
    const double sz = n.z >= 0.0f ? 1.0 : -1.0, a = -1.0 / (sz + double(n.z));
    const double ra = (1.0 + kGlDiv) + (1.0 + kCpuDiv), rb = ra + 4.0;
    const double b = std::abs(double(n.x) * double(n.y) * a);
    const double tx =
        kU * (rb * std::abs(double(n.x) * double(n.x) * a) + 2.0 * std::abs(double(f.t.x)));
    const double by =
        kU * (rb * std::abs(double(n.y) * double(n.y) * a) + 2.0 * std::abs(double(f.b.y)));
    // f.n is passed through; n.y + n.z is one correctly rounded sum on both sides (exact).
    return std::vector<ExpectedSlot>{within(vec4(f.t, f.n.x), {tx, kU * rb * b, 0, 0}),
                                     within(vec4(f.b, f.n.y + f.n.z), {kU * rb * b, by, 0, 0})};
  };
  return c;
}

ElementCase frame_to_world_case() {
  ElementCase c{"frame_to_world", "ffff", 1, "", nullptr, {}};
  const auto ns = normals();
  for (size_t i = 0; i < ns.size(); ++i)
    for (size_t j = 0; j < 4; ++j) {
      const sh::Frame f = sh::frame_from_normal(ns[i]);
      c.inputs.insert(c.inputs.end(),
                      {words(vec4(f.t, 0)), words(vec4(f.b, 0)), words(vec4(f.n, 0)),
                       words(vec4(ns[(i * 7 + j * 13) % ns.size()] * (j == 3 ? 0.0f : 1.5f), 0))});
    }
  c.glsl =
      "Frame f = Frame(fin(0u).xyz, fin(1u).xyz, fin(2u).xyz);\n"
      "put(0u, vec4(frame_to_world(f, fin(3u).xyz), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const sh::Frame f{vec3(floats(in[0])), vec3(floats(in[1])), vec3(floats(in[2]))};
    const vec3 l(floats(in[3]));
    const vec3 w = sh::frame_to_world(f, l);
    // Three products summed (contracted or not): 3 u of the sum of |terms| per side.
    glm::dvec4 b(0.0);
    for (int i = 0; i < 3; ++i)
      b[i] = kU * 6.0 *
             (std::abs(double(f.t[i]) * double(l.x)) + std::abs(double(f.b[i]) * double(l.y)) +
              std::abs(double(f.n[i]) * double(l.z)));
    return std::vector<ExpectedSlot>{within(vec4(w, 0), b)};
  };
  return c;
}

sh::ParticleEmitterBlock emitter(int k) {
  sh::ParticleEmitterBlock e;
  e.origin_count = k == 0 ? vec4(0.5f, 0.1f, -0.3f, 64.0f) : vec4(-2.0f, 3.0f, 1.0f, 1.0f);
  e.spawn_extent_lifetime =
      k == 0 ? vec4(0.05f, 0.02f, 0.05f, 1.5f) : vec4(0.0f, 1.0f, 0.5f, 0.25f);
  e.velocity_min = vec4(-0.1f, 0.5f, -0.1f, 0.0f);
  e.velocity_max = k == 0 ? vec4(0.1f, 1.2f, 0.1f, 0.0f) : vec4(-0.1f, 0.5f, -0.1f, 0.0f);
  e.acceleration = k == 0 ? vec4(0.0f, -0.3f, 0.0f, 0.0f) : vec4(0.0f);
  e.color_size_start = vec4(4.0f, 2.0f, 0.5f, 0.02f);
  e.color_size_end = vec4(0.5f, 0.1f, 0.0f, 0.005f);
  return e;
}

// particle_state's bound. birth = id/count*lifetime (division + 1 u), since = time - birth,
// age = since - cycle*lifetime (1 u each, cycle equal on both sides by the grid's choice), then
// position = spawn + v age + a (age^2/2) and the mixes with u = age/lifetime.
std::vector<ExpectedSlot> particle_expect(const sh::ParticleEmitterBlock& e, uint32_t em,
                                          uint32_t id, float time) {
  const sh::ParticleState p = sh::particle_state(e, em, id, time);
  const double life = std::max(double(e.spawn_extent_lifetime.w), 1e-6),
               count = std::max(double(e.origin_count.w), 1.0);
  const double birth = double(id) / count * life, since = double(time) - birth,
               cycle = std::floor(since / life);
  const double age = since - cycle * life;
  const double d_age = kU * ((1.0 + kGlDiv + 1.0 + kCpuDiv + 2.0) * birth +
                             2.0 * (std::abs(since) + std::abs(cycle * life) + age));
  const double u = age / life, d_u = d_age / life + kU * (kGlDiv + kCpuDiv) * u;
  glm::dvec4 bp(0.0), bc(0.0);
  for (int i = 0; i < 3; ++i) {
    const double o = std::abs(double(e.origin_count[i])),
                 ext = std::abs(double(e.spawn_extent_lifetime[i]));
    const double v0 = std::abs(double(e.velocity_min[i])), v1 = std::abs(double(e.velocity_max[i]));
    const double v = std::max(v0, v1), acc = std::abs(double(e.acceleration[i]));
    // spawn: (2r - 1) exact, * extent, + origin: 2 u of |o| + |ext| per side; velocity mix 3 u
    // of |v0| + |v1| per side; v age, a (0.5 age age), the two sums: 1-3 u of each term per side.
    bp[i] = kU * (4.0 * (o + ext) + 6.0 * (v0 + v1) * age + 4.0 * (o + ext + v * age) +
                  10.0 * acc * age * age) +
            (v + acc * age) * d_age;
    const double c0 = std::abs(double(e.color_size_start[i])),
                 c1 = std::abs(double(e.color_size_end[i]));
    bc[i] = kU * 6.0 * (c0 + c1) + std::abs(c1 - c0) * d_u;
  }
  const double r0 = std::abs(double(e.color_size_start.w)),
               r1 = std::abs(double(e.color_size_end.w));
  bp.w = kU * 6.0 * (r0 + r1) + std::abs(r1 - r0) * d_u;
  bc.w = d_u;
  return {within(p.position_radius, bp), within(p.color_age, bc)};
}

ElementCase particle_state_case() {
  ElementCase c{"particle_state", "ffffffffu", 2, "", nullptr, {}};
  const std::vector<float> times = {0.0f, 0.01f, 0.37f, 1.0f, 2.2f, 17.3f, 123.45f};
  for (int k = 0; k < 2; ++k) {
    const sh::ParticleEmitterBlock e = emitter(k);
    for (uint32_t id = 0; id < 64; id += 3)
      for (float t : times) {
        // The cycle floor((t - birth)/lifetime) jumps at each respawn: the two sides' quotients
        // differ by up to ~16 u |q| (birth, since, the division), so points within 1e-4 max(1, |q|)
        // of an integer could land on different cycles and are left out.
        const double life = std::max(double(e.spawn_extent_lifetime.w), 1e-6);
        const double q =
            (double(t) - double(id) / std::max(double(e.origin_count.w), 1.0) * life) / life;
        if (std::abs(q - std::round(q)) < 1e-4 * std::max(1.0, std::abs(q))) continue;
        c.inputs.insert(
            c.inputs.end(),
            {words(e.origin_count), words(e.spawn_extent_lifetime), words(e.velocity_min),
             words(e.velocity_max), words(e.acceleration), words(e.color_size_start),
             words(e.color_size_end), words(vec4(t)), uvec4(uint32_t(k + 3), id, 0u, 0u)});
      }
  }
  c.glsl =
      "ParticleEmitterBlock e = ParticleEmitterBlock(fin(0u), fin(1u), fin(2u), fin(3u), fin(4u), "
      "fin(5u), fin(6u));\n"
      "uvec4 k = uin(8u);\n"
      "ParticleState p = particle_state(e, k.x, k.y, fin(7u).x);\n"
      "put(0u, p.position_radius); put(1u, p.color_age);";
  c.cpu = [](const uvec4* in) {
    sh::ParticleEmitterBlock e{floats(in[0]), floats(in[1]), floats(in[2]), floats(in[3]),
                               floats(in[4]), floats(in[5]), floats(in[6])};
    return particle_expect(e, in[8].x, in[8].y, floats(in[7]).x);
  };
  return c;
}

ElementCase particle_splat_case() {
  ElementCase c{"particle_profile, particle_voxel_radiance", "ff", 2, "", nullptr, {}};
  for (float radius : {0.0f, 1e-9f, 0.005f, 0.02f, 1.0f})
    for (float rho : {0.0f, 0.001f, 0.0049f, 0.005f, 0.01f, 0.5f, 2.0f})
      c.inputs.insert(c.inputs.end(), {words(vec4(4.0f, 2.0f, 0.5f, radius)),
                                       words(vec4(rho, 1.0f / 64.0f, 0, 0))});
  c.glsl =
      "vec4 a = fin(0u), b = fin(1u);\n"
      "put(0u, vec4(particle_profile(b.x, a.w), 0.0f, 0.0f, 0.0f));\n"
      "put(1u, vec4(particle_voxel_radiance(ParticleState(a, vec4(a.xyz, 0.5f)), b.y), 0.0f));";
  c.cpu = [](const uvec4* in) {
    const vec4 a = floats(in[0]), b = floats(in[1]);
    const float prof = sh::particle_profile(b.x, a.w);
    const vec3 rad = sh::particle_voxel_radiance(sh::ParticleState{a, vec4(vec3(a), 0.5f)}, b.y);
    // profile: q = rho/r (division), q^2 2x + 1 u, 1 - q^2 1 u of the result per side.
    const double q = double(b.x) / std::max(double(a.w), 1e-8);
    const double prof_b =
        kU * ((2.0 * kGlDiv + 1.0 + 2.0 * kCpuDiv + 1.0) * q * q + 2.0 * double(prof));
    // radiance: 0.5 pi exact, r r 2 u, vs vs 1 u, division, colour 1 u: GL 9 u, C++ 5 u.
    const double rad_u = 4.0 + kGlDiv + 4.0 + kCpuDiv;
    return std::vector<ExpectedSlot>{
        within(vec4(prof, 0, 0, 0), {prof_b, 0, 0, 0}),
        within(vec4(rad, 0), glm::dvec4(kU * rad_u * glm::abs(glm::dvec3(rad)), 0))};
  };
  return c;
}

std::vector<ElementCase> hash_users() {
  return {hash_case(), cone_block_case(), fixed_point_case()};
}

// glTF alphaMode: the one alpha test every pass applies (exact: comparisons and a select).
ElementCase alpha_case() {
  ElementCase c{"effective_alpha_cutoff, alpha_discards", "uf", 1, "", nullptr, {}};
  const float alphas[] = {0.0f, 0.25f, 0.49999997f, 0.5f, 0.50000006f, 0.7f, 1.0f};
  const float cutoffs[] = {0.0f, 0.5f, 0.6f, 1.0f};
  for (uint32_t mode = 0; mode < 3; ++mode)
    for (float a : alphas)
      for (float cut : cutoffs)
        c.inputs.insert(c.inputs.end(), {uvec4(mode, 0u, 0u, 0u), words(vec4(a, cut, 0, 0))});
  c.glsl =
      "int m = int(uin(0u).x); vec4 f = fin(1u);\n"
      "putu(0u, uvec4(alpha_discards(m, f.x, f.y) ? 1u : 0u,\n"
      "               floatBitsToUint(effective_alpha_cutoff(m, f.y)), "
      "floatBitsToUint(BLEND_ALPHA_CUTOFF),\n"
      "               uint(ALPHA_MODE_OPAQUE + 2 * ALPHA_MODE_MASK + 4 * ALPHA_MODE_BLEND)));";
  c.cpu = [](const uvec4* in) {
    const int m = int(in[0].x);
    const vec4 f = floats(in[1]);
    const float cut = sh::effective_alpha_cutoff(m, f.y), blend = sh::BLEND_ALPHA_CUTOFF;
    uint32_t cut_bits = 0, blend_bits = 0;
    std::memcpy(&cut_bits, &cut, 4);
    std::memcpy(&blend_bits, &blend, 4);
    return std::vector<ExpectedSlot>{exact_u(uvec4(
        sh::alpha_discards(m, f.x, f.y) ? 1u : 0u, cut_bits, blend_bits,
        uint32_t(sh::ALPHA_MODE_OPAQUE + 2 * sh::ALPHA_MODE_MASK + 4 * sh::ALPHA_MODE_BLEND)))};
  };
  return c;
}

std::vector<ElementCase> all_cases() {
  return {constants_case(),
          hash_case(),
          fixed_point_case(),
          ggx_case(),
          g1_case(),
          fresnel_case(),
          surface_pbr_case(),
          diffuse_weight_case(),
          lobes_case(),
          cook_torrance_case(),
          view_cosine_case(),
          lobes_nv_case(),
          cook_torrance_nv_case(),
          spot_cone_case(),
          hard_spot_case(),
          range_window_case(),
          step_correction_case(),
          spot_irradiance_case(),
          directional_irradiance_case(),
          point_irradiance_case(),
          punctual_irradiance_case(),
          to_light_direction_case(),
          cone_direction_case(),
          cone_block_case(),
          aperture_case(),
          frame_case(),
          frame_to_world_case(),
          particle_state_case(),
          particle_splat_case(),
          alpha_case()};
}

}  // namespace

// No shared function escapes: every VCT_FN / VCT_FP_FN declared in the headers the shaders get
// is called by some case's GLSL (a function added to vct_shared.h needs a case here).
TEST(SharedHeaderElement, EverySharedFunctionHasACase) {
  const std::string header = shared_header_glsl();
  std::string called;
  for (const ElementCase& c : all_cases()) called += c.glsl + "\n";
  const std::regex decl(R"(VCT_(?:FP_)?FN\s+\w+\s+(\w+)\s*\()");
  size_t functions = 0;
  for (auto it = std::sregex_iterator(header.begin(), header.end(), decl);
       it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    ++functions;
    EXPECT_TRUE(std::regex_search(called, std::regex("\\b" + name + "\\s*\\(")))
        << name << " (ref/shared/) has no element case";
  }
  EXPECT_GE(functions, 32u);  // the regex still finds the declarations (32 today)
}

TEST(SharedHeaderElement, EveryFunctionMatchesTheCppBuildWithinItsGlslBound) {
  VCT_REQUIRE_GL();
  const std::vector<ElementCase> cases = all_cases();
  const std::vector<ElementResult> results = run_element_cases(cases, shared_header_glsl());
  ASSERT_EQ(results.size(), cases.size());
  for (const ElementResult& r : results) {
    std::printf("[element] %-62s %5zu points  worst %.3g x bound, %.0f ulp, |diff| %.3g\n  %s\n",
                r.function.c_str(), r.points, r.worst_ratio, r.worst_ulps, r.worst_abs,
                r.message.c_str());
    EXPECT_GE(r.points, 1u);
    EXPECT_TRUE(r.pass) << r.message;
  }
}

// The harness can fail, and pins the failure: Schlick's exponent 4 instead of 5 in the GLSL build
// only must be reported for fresnel_schlick and the four functions that call it, nothing else.
TEST(SharedHeaderElement, APerturbedSchlickExponentIsPinnedToFresnel) {
  VCT_REQUIRE_GL();
  const std::vector<ElementCase> cases = all_cases();
  const std::string header =
      shared_header_glsl({{"float m5 = m * m * m * m * m;", "float m5 = m * m * m * m;"}});
  std::set<std::string> failed;
  std::string fresnel_message;
  for (const ElementResult& r : run_element_cases(cases, header)) {
    if (!r.pass) failed.insert(r.function);
    if (r.function == "fresnel_schlick") fresnel_message = r.message;
  }
  EXPECT_EQ(failed,
            (std::set<std::string>{"fresnel_schlick", "cook_torrance_lobes", "cook_torrance",
                                   "cook_torrance_lobes_nv", "cook_torrance_nv"}));
  EXPECT_NE(fresnel_message.find("fresnel_schlick: GL differs from C++ beyond its bound"),
            std::string::npos)
      << fresnel_message;
  EXPECT_NE(fresnel_message.find("input ("), std::string::npos) << fresnel_message;
  std::printf("[element] perturbed: %s\n", fresnel_message.c_str());
}

// The exact comparisons fail too: one constant of pcg_hash changed in the GLSL build is reported
// for the hash functions and for the cone rotation built on them, not for the fixed-point
// functions run alongside.
TEST(SharedHeaderElement, APerturbedHashConstantFailsTheExactComparisons) {
  VCT_REQUIRE_GL();
  const std::string header = shared_header_glsl({{"* 277803737u", "* 277803739u"}});
  std::set<std::string> failed;
  for (const ElementResult& r : run_element_cases(hash_users(), header))
    if (!r.pass) {
      failed.insert(r.function);
      EXPECT_NE(r.message.find("exact expected"), std::string::npos) << r.message;
    }
  EXPECT_EQ(failed, (std::set<std::string>{
                        "pcg_hash, hash_combine, hash_to_unit, particle_random",
                        "diffuse_cone_count, diffuse_cone_weight, diffuse_cone_rotation"}));
}

}  // namespace vct::gl::test
