#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace vct::cmp {

float luminance(const Image& img, int x, int y) {
  const float* p = img.pixel(x, y);
  if (img.channels < 3) return p[0];
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

Image luminance_image(const Image& img) {
  Image out(img.width, img.height, 1);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) out.at(x, y, 0) = luminance(img, x, y);
  return out;
}

ImageMetrics image_metrics(const Image& test, const Image& reference) {
  if (test.width != reference.width || test.height != reference.height)
    throw InputError("", "images differ in size: " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                             " vs " + std::to_string(reference.width) + "x" + std::to_string(reference.height));
  const int ch = std::min({test.channels, reference.channels, 3});
  ImageMetrics m;
  double se = 0, rse = 0, bias = 0, sum_r = 0, sum_t = 0;
  size_t n = 0;
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x)
      for (int c = 0; c < ch; ++c) {
        const double t = test.at(x, y, c), r = reference.at(x, y, c), d = t - r;
        se += d * d;
        rse += d * d / (r * r + m.rel_mse_epsilon);
        bias += d;
        sum_r += r;
        sum_t += t;
        m.max_abs = std::max(m.max_abs, std::abs(d));
        ++n;
      }
  if (n == 0) return m;
  m.mse = se / double(n);
  m.rel_mse = rse / double(n);
  m.mean_bias = bias / double(n);
  m.relative_bias = sum_r != 0.0 ? bias / sum_r : 0.0;
  m.mean_reference = sum_r / double(n);
  m.mean_test = sum_t / double(n);
  m.ssim = ssim(luminance_image(test), luminance_image(reference));
  return m;
}

namespace {
// Separable Gaussian blur (11 taps, sigma 1.5), edges clamped.
Image blur(const Image& in) {
  constexpr int kR = 5;
  double w[2 * kR + 1], sum = 0;
  for (int i = -kR; i <= kR; ++i) sum += w[i + kR] = std::exp(-0.5 * i * i / (1.5 * 1.5));
  for (double& v : w) v /= sum;
  Image tmp(in.width, in.height, 1), out(in.width, in.height, 1);
  auto clampi = [](int v, int hi) { return std::clamp(v, 0, hi - 1); };
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0;
      for (int i = -kR; i <= kR; ++i) s += w[i + kR] * double(in.at(clampi(x + i, in.width), y, 0));
      tmp.at(x, y, 0) = float(s);
    }
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0;
      for (int i = -kR; i <= kR; ++i) s += w[i + kR] * double(tmp.at(x, clampi(y + i, in.height), 0));
      out.at(x, y, 0) = float(s);
    }
  return out;
}

Image product(const Image& a, const Image& b) {
  Image p(a.width, a.height, 1);
  for (size_t i = 0; i < p.data.size(); ++i) p.data[i] = a.data[i] * b.data[i];
  return p;
}
}  // namespace

double ssim(const Image& t, const Image& r) {
  if (t.empty() || r.empty()) return 1.0;
  float peak = 1.0f;
  for (float v : r.data) peak = std::max(peak, v);
  const double c1 = std::pow(0.01 * double(peak), 2), c2 = std::pow(0.03 * double(peak), 2);
  const Image mt = blur(t), mr = blur(r), tt = blur(product(t, t)), rr = blur(product(r, r)), tr = blur(product(t, r));
  double sum = 0;
  for (size_t i = 0; i < mt.data.size(); ++i) {
    const double mx = double(mt.data[i]), my = double(mr.data[i]);
    const double vx = double(tt.data[i]) - mx * mx, vy = double(rr.data[i]) - my * my,
                 cxy = double(tr.data[i]) - mx * my;
    sum += ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
  }
  return sum / double(mt.data.size());
}

}  // namespace vct::cmp
