// The shared Cook–Torrance BRDF (shared/vct_shared.h) against double-precision and hand-computed
// values: GGX D keeps its precision for smooth surfaces, integrates to one, and the two lobes
// the path tracer splits the AOVs by add up to the BRDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "shared/vct_shared.h"

namespace vct {
namespace {

/// GGX D in double, the textbook form alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
double ggx_double(double cos_h, double roughness) {
  const double a2 = std::pow(roughness, 4.0);
  const double d = cos_h * cos_h * (a2 - 1.0) + 1.0;
  return a2 / (M_PI * d * d);
}

// The old float form (1 - (n.h)^2 cancelling) was 8 % too high near the peak at roughness 0.03.
TEST(SharedBrdf, GgxKeepsPrecisionForSmoothSurfaces) {
  const vec3 n(0.0f, 0.0f, 1.0f);
  for (float roughness : {sh::MIN_ROUGHNESS, 0.05f, 0.1f, 0.5f, 1.0f}) {
    for (double theta : {0.0, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 0.1, 0.7, 1.5}) {
      const vec3 h(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
      // Reference on the float h actually passed, so only the function's own rounding counts.
      const double cos_h = double(h.z) / std::hypot(double(h.x), double(h.z));
      const double expected = ggx_double(cos_h, roughness);
      const double got = sh::ggx_distribution(n, h, roughness);
      EXPECT_NEAR(got / expected, 1.0, 1e-4) << "roughness " << roughness << " theta " << theta;
    }
  }
}

TEST(SharedBrdf, GgxBelowTheSurfaceIsTheGrazingValue) {
  const vec3 n(0.0f, 0.0f, 1.0f);
  const float r = 0.5f, a2 = r * r * r * r;
  EXPECT_FLOAT_EQ(sh::ggx_distribution(n, vec3(0.6f, 0.0f, -0.8f), r), a2 / sh::SH_PI);
  EXPECT_FLOAT_EQ(sh::ggx_distribution(n, vec3(1.0f, 0.0f, 0.0f), r), a2 / sh::SH_PI);
}

/// Integral of D(h) (n.h) over the hemisphere (= 1 for a normalized NDF), in double over the
/// float function: Simpson on geometrically growing intervals, fine near the lobe's peak.
double projected_ndf_integral(float roughness) {
  const vec3 n(0.0f, 0.0f, 1.0f);
  auto integrand = [&](double t) {
    const vec3 h(float(std::sin(t)), 0.0f, float(std::cos(t)));
    return double(sh::ggx_distribution(n, h, roughness)) * std::cos(t) * std::sin(t) * 2.0 * M_PI;
  };
  double sum = 0.0, a = 0.0, b = 1e-6;
  while (a < 0.5 * M_PI) {
    b = std::min(b, 0.5 * M_PI);
    sum += (b - a) / 6.0 * (integrand(a) + 4.0 * integrand(0.5 * (a + b)) + integrand(b));
    a = b;
    b = a * 1.02;
  }
  return sum;
}

TEST(SharedBrdf, GgxIsNormalized) {
  for (float roughness : {sh::MIN_ROUGHNESS, 0.1f, 0.4f, 1.0f})
    EXPECT_NEAR(projected_ndf_integral(roughness), 1.0, 2e-3) << "roughness " << roughness;
}

TEST(SharedBrdf, LobesAddUpToCookTorrance) {
  const sh::SurfacePbr s = sh::surface_pbr(vec3(0.8f, 0.4f, 0.2f), 0.3f, 0.35f, 1.0f, vec3(1.0f));
  const vec3 n(0.0f, 0.0f, 1.0f), v = glm::normalize(vec3(0.3f, 0.1f, 1.0f));
  const vec3 l = glm::normalize(vec3(-0.5f, 0.2f, 0.7f));
  const sh::BrdfLobes b = sh::cook_torrance_lobes(s, n, v, l);
  EXPECT_EQ(sh::cook_torrance(s, n, v, l), b.diffuse + b.specular);
  const vec3 f = sh::fresnel_schlick(s.f0, s.f90, glm::dot(glm::normalize(v + l), v));
  const vec3 kd = (vec3(1.0f) - f) * (1.0f - s.metallic);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(b.diffuse[c], kd[c] * s.albedo[c] * sh::SH_INV_PI);
}

// v = l = n: h = n, F = f0, G = 1 (Schlick-GGX G1(1) = 1), D = 1 / (pi alpha^2), so the specular
// lobe is f0 / (4 pi alpha^2).
TEST(SharedBrdf, SpecularLobeAtNormalIncidenceByHand) {
  const float r = 0.5f, alpha = r * r;
  const sh::SurfacePbr s = sh::surface_pbr(vec3(0.5f), 0.0f, r, 1.0f, vec3(1.0f));
  const vec3 n(0.0f, 0.0f, 1.0f);
  const sh::BrdfLobes b = sh::cook_torrance_lobes(s, n, n, n);
  EXPECT_FLOAT_EQ(b.specular.x, 0.04f / (4.0f * sh::SH_PI * alpha * alpha));
  EXPECT_FLOAT_EQ(b.diffuse.x, 0.96f * 0.5f * sh::SH_INV_PI);
}

TEST(SharedBrdf, NothingBelowTheHorizon) {
  const sh::SurfacePbr s = sh::surface_pbr(vec3(0.5f), 0.0f, 0.5f, 1.0f, vec3(1.0f));
  const vec3 n(0.0f, 0.0f, 1.0f), v(0.0f, 0.0f, 1.0f);
  const sh::BrdfLobes b = sh::cook_torrance_lobes(s, n, v, glm::normalize(vec3(1.0f, 0.0f, -0.1f)));
  EXPECT_EQ(b.diffuse, vec3(0.0f));
  EXPECT_EQ(b.specular, vec3(0.0f));
}


// The view cosine's modes (setting n_dot_v, issue 39) on a view below the surface (n.v = -0.6, a
// silhouette pixel): zero (ours) leaves both lobes 0; abs shades as if n.v were 0.6; clamp as if
// it were 1e-4. By hand from the pieces: h = normalize(v + l), F(h.v), D(n, h), G1 of each
// cosine, spec = F D G / (4 n.l n.v'), diffuse = (1 - F) albedo / pi (dielectric).
TEST(SharedBrdf, ViewCosineModesByHand) {
  EXPECT_EQ(sh::view_cosine(-0.6f, sh::NV_ZERO), -0.6f);
  EXPECT_EQ(sh::view_cosine(-0.6f, sh::NV_ABS), 0.6f);
  EXPECT_EQ(sh::view_cosine(-0.6f, sh::NV_CLAMP), 1e-4f);
  EXPECT_EQ(sh::view_cosine(0.3f, sh::NV_CLAMP), 0.3f);
  const float r = 0.5f;
  const sh::SurfacePbr s = sh::surface_pbr(vec3(0.5f), 0.0f, r, 1.0f, vec3(1.0f));
  const vec3 n(0.0f, 0.0f, 1.0f), v(0.8f, 0.0f, -0.6f), l(0.0f, 0.6f, 0.8f);
  const sh::BrdfLobes zero = sh::cook_torrance_lobes_nv(s, n, v, l, sh::NV_ZERO);
  EXPECT_EQ(zero.diffuse, vec3(0.0f));
  EXPECT_EQ(zero.specular, vec3(0.0f));
  const vec3 h = glm::normalize(v + l);
  const float f = sh::fresnel_schlick(s.f0, s.f90, std::max(glm::dot(h, v), 0.0f)).x;
  const float d = sh::ggx_distribution(n, h, r);
  for (const auto& [mode, nv] : {std::pair{sh::NV_ABS, 0.6f}, std::pair{sh::NV_CLAMP, 1e-4f}}) {
    const sh::BrdfLobes b = sh::cook_torrance_lobes_nv(s, n, v, l, mode);
    const float g = sh::schlick_ggx_g1(0.8f, r) * sh::schlick_ggx_g1(nv, r);
    EXPECT_NEAR(b.specular.x, f * d * g / (4.0f * 0.8f * nv), 1e-5f * b.specular.x) << mode;
    EXPECT_NEAR(b.diffuse.x, (1.0f - f) * 0.5f * sh::SH_INV_PI, 1e-6f) << mode;
    EXPECT_EQ(sh::cook_torrance_nv(s, n, v, l, mode), b.diffuse + b.specular);
  }
  // The oracle's functions are the zero mode.
  EXPECT_EQ(sh::cook_torrance(s, n, v, l), vec3(0.0f));
}

}  // namespace
}  // namespace vct
