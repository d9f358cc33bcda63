// Sampling of emissive triangles: the triangle choice follows area x emission luminance (pdf_area
// integrates to 1 over the emitters), and points are uniform on a triangle (chi^2 on a barycentric
// grid). Together with the MIS furnaces this checks every pdf the emitter NEE uses.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "chi2.h"
#include "pt/emissive_lights.h"
#include "pt/rng.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

Scene three_emitters() {
  Scene s;
  const uint32_t dim = test::add_material(s, test::lambertian(vec3(0.5f), vec3(1.0f)));
  const uint32_t bright = test::add_material(s, test::lambertian(vec3(0.5f), vec3(0.0f, 3.0f, 0.0f)));
  const uint32_t none = test::add_material(s, test::lambertian(vec3(0.5f)));
  test::add_triangle(s, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), dim);     // area 0.5, lum 1
  test::add_triangle(s, vec3(0, 0, 1), vec3(2, 0, 1), vec3(0, 1, 1), bright);  // area 1, lum 3*0.7152
  test::add_triangle(s, vec3(0, 0, 2), vec3(5, 0, 2), vec3(0, 5, 2), none);    // not an emitter
  test::finish(s);
  return s;
}

TEST(EmitterSampling, TriangleChoiceFollowsAreaTimesLuminance) {
  const Scene s = three_emitters();
  const EmissiveTriangles lights(s);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights.pdf_area(2), 0.0f);
  const double w0 = 0.5 * 1.0, w1 = 1.0 * 3.0 * 0.7152;
  const double p0 = w0 / (w0 + w1);
  // pdf_area = selection probability / area, so it integrates to 1 over the emitters.
  EXPECT_NEAR(double(lights.pdf_area(0)) * 0.5, p0, 1e-6);
  EXPECT_NEAR(double(lights.pdf_area(1)), 1.0 - p0, 1e-6);
  Pcg32 rng(5u, 1u);
  constexpr int kN = 200000;
  int first = 0;
  for (int i = 0; i < kN; ++i) {
    const float u = rng.next_float();
    const EmissiveTriangles::Sample smp = lights.sample(u, rng.next_2d());
    ASSERT_NE(smp.triangle, 2u);
    first += smp.triangle == 0 ? 1 : 0;
    ASSERT_EQ(smp.pdf_area, lights.pdf_area(smp.triangle));
  }
  EXPECT_NEAR(double(first) / kN, p0, 4.0 * std::sqrt(p0 * (1 - p0) / kN));
}

TEST(EmitterSampling, PointsAreUniformOnTheTriangle) {
  const Scene s = three_emitters();
  const EmissiveTriangles lights(s);
  // Barycentric grid of 10x10 cells over (b1, b2); a cell's expected share is its area inside
  // the triangle b1 + b2 <= 1 (full cells 0.01, diagonal cells 0.005) over the area 0.5.
  constexpr int kG = 10, kN = 400000;
  std::vector<double> observed(kG * kG, 0.0);
  Pcg32 rng(11u, 2u);
  for (int i = 0; i < kN; ++i) {
    const EmissiveTriangles::Sample smp = lights.sample(0.0f, rng.next_2d());  // always triangle 0
    ASSERT_EQ(smp.triangle, 0u);
    ASSERT_LE(smp.b1 + smp.b2, 1.0f + 1e-6f);
    const int a = std::min(kG - 1, int(smp.b1 * kG)), b = std::min(kG - 1, int(smp.b2 * kG));
    observed[size_t(a * kG + b)] += 1.0;
  }
  double chi2 = 0.0;
  int dof = -1;
  for (int a = 0; a < kG; ++a)
    for (int b = 0; b < kG; ++b) {
      const double area = a + b < kG - 1 ? 0.01 : (a + b == kG - 1 ? 0.005 : 0.0);
      const double e = area / 0.5 * kN;
      if (e == 0.0) {
        EXPECT_EQ(observed[size_t(a * kG + b)], 0.0);
        continue;
      }
      chi2 += (observed[size_t(a * kG + b)] - e) * (observed[size_t(a * kG + b)] - e) / e;
      ++dof;
    }
  const double p = test::gamma_q(0.5 * dof, 0.5 * chi2);
  std::printf("[triangle sampling] chi2=%.1f dof=%d p=%.4f\n", chi2, dof, p);
  EXPECT_GT(p, 1e-3);
}

}  // namespace
}  // namespace vct::pt
