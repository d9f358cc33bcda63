#include "core/steiner_count.h"

#include <algorithm>
#include <cmath>

namespace vct {

SteinerTerms steiner_terms(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  // A |n_i| is the area of the projection along axis i: half the cross product's component.
  const glm::dvec3 cross = glm::cross(b - a, c - a);
  const glm::dvec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
  SteinerTerms t;
  t.projected_area = 0.5 * (std::abs(cross.x) + std::abs(cross.y) + std::abs(cross.z));
  t.extent = (hi.x - lo.x) + (hi.y - lo.y) + (hi.z - lo.z);
  return t;
}

double steiner_voxels(const SteinerTerms& sums, uint64_t triangles, int n) {
  const double h = double(n);  // voxels per unit: areas scale by n^2, lengths by n
  return sums.projected_area * h * h + sums.extent * h + double(triangles);
}

}  // namespace vct
