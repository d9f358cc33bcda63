// A hand-made case of attribute extrapolation under vertex snapping (freedoms/fragment_slack.h,
// voxel_snap_reach): the triangle (4,4)-(4.25,4)-(4,4.25) in pixel units and the pixel centre
// (4.5, 4.5) outside it, where non-centroid attributes are extrapolated (GL 4.5 §14.9.3).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace vct::test {

/// How far the point of the original triangle with the centre's barycentrics in the triangle whose
/// vertices moved by `d` (x0, y0, x1, y1, x2, y2) lies from the centre.
inline glm::dvec2 extrapolated_point_move(const double (&d)[6]) {
  const glm::dvec2 p[3] = {{4.0, 4.0}, {4.25, 4.0}, {4.0, 4.25}}, c(4.5, 4.5);
  const glm::dvec2 q0 = p[0] + glm::dvec2(d[0], d[1]), q1 = p[1] + glm::dvec2(d[2], d[3]),
                   q2 = p[2] + glm::dvec2(d[4], d[5]);
  const glm::dvec2 e1 = q1 - q0, e2 = q2 - q0, r = c - q0;
  const double det = e1.x * e2.y - e2.x * e1.y;
  const double l1 = (r.x * e2.y - e2.x * r.y) / det, l2 = (e1.x * r.y - r.x * e1.y) / det;
  return (1.0 - l1 - l2) * p[0] + l1 * p[1] + l2 * p[2] - c;
}

/// The largest per-axis move over the 64 corners of every vertex coordinate moved by +-step.
inline double largest_corner_move(double step) {
  double largest = 0.0;
  for (int k = 0; k < 64; ++k) {
    double d[6];
    for (int i = 0; i < 6; ++i) d[i] = (k >> i & 1) ? step : -step;
    const glm::dvec2 e = extrapolated_point_move(d);
    largest = std::max({largest, std::abs(e.x), std::abs(e.y)});
  }
  return largest;
}

}  // namespace vct::test
