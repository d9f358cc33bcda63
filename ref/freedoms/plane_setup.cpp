#include "freedoms/plane_setup.h"

#include <algorithm>
#include <cmath>

namespace vct {

namespace {

// The bound with vertex k first, over a box of extent (wx, wy) pixels from it whose farthest
// coordinates from the window origin are (ox, oy).
double setup_error_from(const RasterTriangle& t, int k, double wx, double wy, double ox, double oy) {
  constexpr double g = 4.0 * kFloatRoundoff;
  const int j1 = (k + 1) % 3, j2 = (k + 2) % 3;
  const double s = 1.0 / double(kSubpixelScale);
  const double dx1 = double(t.x[j1] - t.x[k]) * s, dy1 = double(t.y[j1] - t.y[k]) * s, dz1 = t.z[j1] - t.z[k];
  const double dx2 = double(t.x[j2] - t.x[k]) * s, dy2 = double(t.y[j2] - t.y[k]) * s, dz2 = t.z[j2] - t.z[k];
  const double area = dx1 * dy2 - dx2 * dy1;
  if (area == 0.0) return 0.0;  // not rasterized
  const double s_area = std::abs(dx1 * dy2) + std::abs(dx2 * dy1);
  const double dzdx = (dz1 * dy2 - dz2 * dy1) / area, dzdy = (dx1 * dz2 - dx2 * dz1) / area;
  const double s_x = std::abs(dz1 * dy2) + std::abs(dz2 * dy1), s_y = std::abs(dx1 * dz2) + std::abs(dx2 * dz1);
  const double err_x = (g * s_x + std::abs(dzdx) * g * s_area) / std::abs(area) + kFloatRoundoff * std::abs(dzdx);
  const double err_y = (g * s_y + std::abs(dzdy) * g * s_area) / std::abs(area) + kFloatRoundoff * std::abs(dzdy);
  // Evaluated from vertex k, z_k + dz/dx (x - x_k) + ..., or from the window origin through
  // a0 = z_k - dz/dx x_k - dz/dy y_k (llvmpipe's form): three roundings of terms at most this large.
  const double terms = std::abs(t.z[k]) + std::abs(dzdx) * (wx + 2.0 * ox) + std::abs(dzdy) * (wy + 2.0 * oy);
  return err_x * wx + err_y * wy + 3.0 * kFloatRoundoff * terms;
}

}  // namespace

double plane_setup_margin(const RasterTriangle& t) {
  // Every covered centre lies in the pixel box [xmin, xmax + 1] x [ymin, ymax + 1] (before the
  // viewport clamp: the vertices' own box, which holds the triangle).
  const double s = 1.0 / double(kSubpixelScale);
  const double x0 = double(std::min({t.x[0], t.x[1], t.x[2]})) * s, x1 = double(std::max({t.x[0], t.x[1], t.x[2]})) * s;
  const double y0 = double(std::min({t.y[0], t.y[1], t.y[2]})) * s, y1 = double(std::max({t.y[0], t.y[1], t.y[2]})) * s;
  double worst = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double vx = double(t.x[k]) * s, vy = double(t.y[k]) * s;
    worst = std::max(worst, setup_error_from(t, k, std::max(vx - x0, x1 - vx), std::max(vy - y0, y1 - vy),
                                             std::max(std::abs(x0), std::abs(x1)), std::max(std::abs(y0), std::abs(y1))));
  }
  return worst;
}

}  // namespace vct
