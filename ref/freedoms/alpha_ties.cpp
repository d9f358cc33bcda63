#include "freedoms/alpha_ties.h"

#include <algorithm>
#include <cmath>

#include "scene/alpha_mask.h"
#include "shared/vct_shared.h"
#include "stages/raster.h"

namespace vct {

float alpha_freedom(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                    uint32_t triangle, const vec3& bary) {
  const float centre = base_color_alpha(scene, triangle, bary.y, bary.z);
  const double cx = double(x) + 0.5, cy = double(wb.height()) - double(row) - 0.5;
  glm::dvec2 bc;
  float shift = 0.0f;
  if (wb.at(scene, triangle, cx, cy, bc)) {
    constexpr double s = kVertexSnapStep;
    static constexpr int kShifts[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    for (const auto& k : kShifts) {
      glm::dvec2 bs;
      if (!wb.at(scene, triangle, cx + s * k[0], cy + s * k[1], bs)) continue;
      const float b1 = bary.y + float(bs.x - bc.x), b2 = bary.z + float(bs.y - bc.y);
      shift = std::max(shift, std::abs(base_color_alpha(scene, triangle, b1, b2) - centre));
    }
  }
  return kAlphaWeightSlack + shift;
}

bool alpha_test_may_flip(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                         uint32_t triangle, const vec3& bary) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  if (!m.alpha_tested()) return false;
  const float cutoff = sh::effective_alpha_cutoff(int(m.alpha_mode), m.alpha_cutoff);
  const float alpha = base_color_alpha(scene, triangle, bary.y, bary.z);
  return std::abs(alpha - cutoff) <= alpha_freedom(scene, wb, x, row, triangle, bary);
}

}  // namespace vct
