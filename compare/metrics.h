// Image metrics between a test image and a reference image (docs/compare.md §Metrics):
// MSE, relMSE (stated epsilon, normalised by the REFERENCE), mean signed bias, max |error|,
// and SSIM on luminance (own implementation: Gaussian 11x11, sigma 1.5, Wang et al. 2004).
#pragma once

#include "core/image.h"

namespace vct::cmp {

/// Rec. 709 luminance of an RGB pixel (the first channel for one-channel images).
float luminance(const Image& img, int x, int y);
Image luminance_image(const Image& img);

constexpr double kRelMseEpsilon = 1e-2;  // relMSE = mean((t-r)^2 / (r^2 + eps)), per channel

struct ImageMetrics {
  double mse = 0.0;
  double rel_mse = 0.0;
  double rel_mse_epsilon = kRelMseEpsilon;
  double mean_bias = 0.0;      // mean(t - r) over pixels and channels
  double relative_bias = 0.0;  // sum(t - r) / sum(r)  (0 when the reference sums to 0)
  double max_abs = 0.0;
  double ssim = 1.0;           // luminance SSIM, in [-1, 1]
  double mean_reference = 0.0, mean_test = 0.0;
};

/// Throws InputError when the sizes differ. Only the first min(channels, 3) channels count.
ImageMetrics image_metrics(const Image& test, const Image& reference);

/// Mean SSIM of two one-channel images. Dynamic range L = max(1, max of the reference) so that
/// HDR radiance is not judged on an LDR scale; C1 = (0.01 L)^2, C2 = (0.03 L)^2.
double ssim(const Image& test_lum, const Image& reference_lum);

}  // namespace vct::cmp
