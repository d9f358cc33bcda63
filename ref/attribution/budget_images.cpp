#include "attribution/budget_images.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vct::attr {

namespace {

const vec3 kWhite(1.0f), kBlack(0.0f), kGrey(0.55f), kRed(0.85f, 0.2f, 0.15f), kBlue(0.2f, 0.35f, 0.85f);

void fill_rect(Image& img, int x0, int y0, int x1, int y1, const vec3& c) {
  for (int y = std::max(0, std::min(y0, y1)); y <= std::min(img.height - 1, std::max(y0, y1)); ++y)
    for (int x = std::max(0, x0); x <= std::min(img.width - 1, x1); ++x) img.set_rgb(x, y, c);
}

struct Bar {
  double from = 0.0, to = 0.0, se = 0.0;
  vec3 colour;
};

std::vector<Bar> waterfall_bars(const ComponentBudget& b) {
  std::vector<Bar> bars;
  const double truth = b.rungs.front().mean;
  bars.push_back({0.0, truth, b.rungs.front().se, kGrey});
  double running = truth;
  for (const Term& t : b.terms) {
    bars.push_back({running, running + t.value.mean, t.value.se, t.value.mean >= 0.0 ? kRed : kBlue});
    running += t.value.mean;
  }
  bars.push_back({0.0, b.rungs.back().mean, b.rungs.back().se, kGrey});
  return bars;
}

}  // namespace

Image waterfall_image(const ComponentBudget& b, int width, int height) {
  Image img(width, height, 3, 1.0f);
  const std::vector<Bar> bars = waterfall_bars(b);
  double lo = 0.0, hi = 0.0;
  for (const Bar& bar : bars) {
    lo = std::min({lo, bar.from, bar.to - bar.se});
    hi = std::max({hi, bar.from, bar.to + bar.se});
  }
  if (hi - lo <= 0.0) hi = lo + 1.0;
  const int margin = 10;
  const auto row = [&](double v) {
    return int(std::lround(double(height - 1 - margin) - (v - lo) / (hi - lo) * double(height - 1 - 2 * margin)));
  };
  const int slot = (width - 2 * margin) / int(bars.size());
  for (size_t i = 0; i < bars.size(); ++i) {
    const Bar& bar = bars[i];
    const int x0 = margin + int(i) * slot + slot / 6, x1 = margin + int(i + 1) * slot - slot / 6;
    fill_rect(img, x0, row(bar.from), x1, row(bar.to), bar.colour);
    const int xc = (x0 + x1) / 2;
    fill_rect(img, xc, row(bar.to - bar.se), xc, row(bar.to + bar.se), kBlack);
    fill_rect(img, xc - 3, row(bar.to), xc + 3, row(bar.to), kBlack);
  }
  fill_rect(img, margin, row(0.0), width - margin, row(0.0), kBlack);
  return img;
}

Image term_heat_image(const RungImage& term, const Image& mask, float* scale) {
  Image img(mask.width, mask.height, 3);
  float m = 0.0f;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.at(x, y, 0) > 0.0f) m = std::max(m, float(std::abs(luminance(term.value.rgb(x, y)))));
  if (scale) *scale = m;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y, 0) <= 0.0f) continue;
      const float t = m > 0.0f ? std::clamp(float(luminance(term.value.rgb(x, y))) / m, -1.0f, 1.0f) : 0.0f;
      img.set_rgb(x, y, t >= 0.0f ? glm::mix(kWhite, kRed, t) : glm::mix(kWhite, kBlue, -t));
    }
  return img;
}

}  // namespace vct::attr
