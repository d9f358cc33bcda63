// The cone-interior sampler of the cone-set and specular-cone rungs: uniform in solid angle inside
// the cone (attribution/base_level_ray.h).
#include <gtest/gtest.h>

#include <cmath>

#include "attribution/base_level_ray.h"
#include "pt/rng.h"
#include "shared/vct_shared.h"

namespace vct::attr {
namespace {

// Uniform in solid angle inside half-angle h: cos(theta) is uniform on [cos h, 1], so its mean is
// (1 + cos h) / 2 and its variance (1 - cos h)^2 / 12; the sample mean of n lies within 4 SE.
// Every sample lies inside the cone (cos theta >= cos h, to float rounding of the frame: 1e-6).
TEST(DirectionInCone, UniformInSolidAngleInsideTheCone) {
  const vec3 axis = glm::normalize(vec3(0.3f, -0.5f, 0.8f));
  for (float aperture_deg : {10.0f, 30.0f, 60.0f, 120.0f}) {
    const float aperture = aperture_deg * (kPi / 180.0f);
    const double cos_h = std::cos(0.5 * double(aperture));
    pt::Pcg32 rng(7, 3);
    const int n = 20000;
    double sum = 0.0, azimuth_x = 0.0;
    const sh::Frame f = sh::frame_from_normal(axis);
    for (int i = 0; i < n; ++i) {
      const vec3 d = direction_in_cone(axis, aperture, rng.next_2d());
      const double c = double(glm::dot(d, axis));
      ASSERT_NEAR(glm::length(d), 1.0f, 1e-6f);
      ASSERT_GE(c, cos_h - 1e-6);
      sum += c;
      azimuth_x += double(glm::dot(d, f.t));  // symmetric about the axis: mean 0
    }
    const double se = (1.0 - cos_h) / std::sqrt(12.0 * n);
    EXPECT_NEAR(sum / n, 0.5 * (1.0 + cos_h), 4.0 * se) << aperture_deg;
    // |d.t| <= sin h, so its mean has SE <= sin h / sqrt(n).
    EXPECT_NEAR(azimuth_x / n, 0.0, 4.0 * std::sin(0.5 * double(aperture)) / std::sqrt(double(n))) << aperture_deg;
  }
}

}  // namespace
}  // namespace vct::attr
