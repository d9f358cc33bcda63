// One rung of an attribution ladder (docs/attribution.md) as per-pixel estimates: the value each
// pixel's estimator gave (linear RGB radiance toward the camera, what the frame's component adds)
// and the variance of that pixel's luminance estimate (0 for deterministic rungs), so the image
// mean gets a Monte Carlo standard error: pixels are estimated from independent random streams,
// so SE(mean) = sqrt(sum_i var_i) / N over the N pixels of the mask.
#pragma once

#include "core/image.h"
#include "core/math.h"

namespace vct::attr {

struct RungImage {
  Image value;     // 3: RGB
  Image lum_var;   // 1: variance of the pixel's luminance estimate (of its mean, not of one sample)
};

/// Rec. 709 luminance, the scalar every budget is stated in.
inline double luminance(const vec3& c) { return 0.2126 * double(c.r) + 0.7152 * double(c.g) + 0.0722 * double(c.b); }

/// A zero rung of w x h (both images allocated).
RungImage make_rung(int width, int height);

/// Streaming mean and variance of one pixel's luminance samples (Welford), plus the RGB sum.
struct PixelSamples {
  int count = 0;
  vec3 sum{0.0f};
  double mean = 0.0, m2 = 0.0;
  void add(const vec3& v);
  /// Stores mean RGB and the variance of the mean luminance (sample variance / count).
  void store(RungImage& r, int x, int y) const;
};

/// Mean luminance over the pixels where mask > 0, and its standard error.
struct MeanSe {
  double mean = 0.0, se = 0.0;
  int pixels = 0;
};
MeanSe masked_mean(const RungImage& r, const Image& mask);

/// a - b per pixel (values) with variances added: the two rungs come from independent streams.
RungImage difference(const RungImage& a, const RungImage& b);

}  // namespace vct::attr
