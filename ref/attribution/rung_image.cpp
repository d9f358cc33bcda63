#include "attribution/rung_image.h"

#include <cmath>

namespace vct::attr {

RungImage make_rung(int width, int height) {
  RungImage r;
  r.value = Image(width, height, 3);
  r.value.channel_names = {"R", "G", "B"};
  r.lum_var = Image(width, height, 1);
  r.lum_var.channel_names = {"Y"};
  return r;
}

void PixelSamples::add(const vec3& v) {
  ++count;
  sum += v;
  const double y = luminance(v), delta = y - mean;
  mean += delta / count;
  m2 += delta * (y - mean);
}

void PixelSamples::store(RungImage& r, int x, int y) const {
  if (count == 0) return;
  r.value.set_rgb(x, y, sum / float(count));
  // Unbiased sample variance over count, divided by count again: the variance of the mean.
  r.lum_var.at(x, y, 0) = count > 1 ? float(m2 / (count - 1) / count) : 0.0f;
}

MeanSe masked_mean(const RungImage& r, const Image& mask) {
  // Summed in row-major order in double: the same result for any thread count.
  double sum = 0.0, var = 0.0;
  int n = 0;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y, 0) <= 0.0f) continue;
      sum += luminance(r.value.rgb(x, y));
      var += double(r.lum_var.at(x, y, 0));
      ++n;
    }
  MeanSe m;
  m.pixels = n;
  if (n == 0) return m;
  m.mean = sum / n;
  m.se = std::sqrt(var) / n;
  return m;
}

RungImage difference(const RungImage& a, const RungImage& b) {
  RungImage d = make_rung(a.value.width, a.value.height);
  for (size_t i = 0; i < d.value.data.size(); ++i) d.value.data[i] = a.value.data[i] - b.value.data[i];
  for (size_t i = 0; i < d.lum_var.data.size(); ++i) d.lum_var.data[i] = a.lum_var.data[i] + b.lum_var.data[i];
  return d;
}

}  // namespace vct::attr
