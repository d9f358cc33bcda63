// A glossy furnace: the camera at the centre of a closed emitting sphere (uniform Le) whose wall
// is a half-metallic glossy material. Every wall point is seen at normal incidence, so the
// one-bounce AOVs have closed forms: Le times the directional albedo of each lobe at v = n,
//   indirect_diffuse  = Le * integral f_d(l) cos dl,   indirect_specular = Le * integral f_s cos,
// with f_d, f_s the two lobes of the shared cook_torrance (a 1D quadrature: at v = n the BRDF
// depends on theta_l only). Checks the lobe split, MIS and the mixture sampler on a glossy surface.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "pt/accumulator.h"
#include "pt/bsdf_sampling.h"
#include "pt/path_tracer.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {
using glm::dvec3;

struct Lobes {
  vec3 diffuse{0.0f}, specular{0.0f};
};

Lobes normal_incidence_albedo(const Material& m) {
  const sh::SurfacePbr pbr = sh::surface_pbr(vec3(m.base_color_factor), m.metallic_factor, m.roughness_factor,
                                             m.specular_factor, m.specular_color_factor);
  const vec3 n(0, 0, 1);
  const BsdfPoint bp = make_bsdf_point(pbr, n, n, n);
  constexpr int kSteps = 200000;
  dvec3 d(0.0), s(0.0);
  for (int i = 0; i < kSteps; ++i) {
    const double th = (i + 0.5) / kSteps * 0.5 * double(kPi);
    const vec3 l(float(std::sin(th)), 0.0f, float(std::cos(th)));
    const BsdfValue f = eval_bsdf(bp, l);
    const double w = std::cos(th) * std::sin(th) * 2.0 * double(kPi) * (0.5 * double(kPi) / kSteps);
    d += dvec3(f.diffuse) * w;
    s += dvec3(f.specular) * w;
  }
  return {vec3(d), vec3(s)};
}

TEST(GlossyFurnace, OneBounceLobesMatchDirectionalAlbedo) {
  Scene scene;
  Material m = test::pbr(vec3(0.8f, 0.6f, 0.4f), 0.5f, 0.35f);
  m.emissive_factor = vec3(1.0f);
  const uint32_t mi = test::add_material(scene, m);
  test::add_icosphere(scene, vec3(0.0f), 1.0f, 4, true, mi);
  scene.camera = test::look_at(vec3(0.0f), vec3(0.2f, 0.1f, -1.0f), vec3(0, 1, 0), 1.0f);
  test::finish(scene);
  PtSettings ps;
  ps.width = ps.height = 24;
  ps.max_depth = 2;
  const PathTracer pt(scene, ps);
  Accumulator acc(ps.width, ps.height);
  pt.render(acc, 32);

  const Lobes expected = normal_incidence_albedo(m);
  for (const auto& [aov, want, name] : {std::tuple{kIndirectDiffuse, expected.diffuse, "diffuse"},
                                        std::tuple{kIndirectSpecular, expected.specular, "specular"}}) {
    const Image mean = acc.mean(aov), var = acc.variance(aov);
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0, v = 0.0;
      for (int y = 0; y < ps.height; ++y)
        for (int x = 0; x < ps.width; ++x) {
          sum += double(mean.at(x, y, c));
          v += double(var.at(x, y, c));
        }
      const double n = double(ps.width) * ps.height, got = sum / n, sigma = std::sqrt(v) / n;
      std::printf("[glossy furnace %s c%d] %.5f expected %.5f (%.2f sigma, sigma %.5f)\n", name, c, got,
                  double(want[c]), (got - double(want[c])) / sigma, sigma);
      EXPECT_LT(sigma, 0.01 * double(want[c]));
      // 4 sigma plus 0.2 % for the facets' small departure from normal incidence.
      EXPECT_NEAR(got, double(want[c]), 4.0 * sigma + 0.002 * double(want[c])) << name << " channel " << c;
    }
  }
}

}  // namespace
}  // namespace vct::pt
