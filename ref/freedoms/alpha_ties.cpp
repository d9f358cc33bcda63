#include "freedoms/alpha_ties.h"

#include <algorithm>
#include <cmath>

#include "scene/alpha_mask.h"
#include "shared/vct_shared.h"
#include "stages/raster.h"

namespace vct {

namespace {

constexpr int kShiftSigns[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

// |alpha - cutoff| <= freedom (an alpha-tested triangle's material).
bool near_cutoff(const Scene& scene, uint32_t triangle, float alpha, float freedom) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  const float cutoff = sh::effective_alpha_cutoff(int(m.alpha_mode), m.alpha_cutoff);
  return std::abs(alpha - cutoff) <= freedom;
}

}  // namespace

float alpha_freedom(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                    uint32_t triangle, const vec3& bary) {
  const float centre = base_color_alpha(scene, triangle, bary.y, bary.z);
  const double cx = double(x) + 0.5, cy = double(wb.height()) - double(row) - 0.5;
  glm::dvec2 bc;
  float shift = 0.0f;
  if (wb.at(scene, triangle, cx, cy, bc)) {
    constexpr double s = kVertexSnapStep;
    for (const auto& k : kShiftSigns) {
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
  if (!triangle_alpha_tested(scene, triangle)) return false;
  const float alpha = base_color_alpha(scene, triangle, bary.y, bary.z);
  return near_cutoff(scene, triangle, alpha, alpha_freedom(scene, wb, x, row, triangle, bary));
}

bool alpha_test_may_flip_affine(const Scene& scene, uint32_t triangle, const vec3& bary, double reach,
                                const glm::dvec2& db_dx, const glm::dvec2& db_dy) {
  if (!triangle_alpha_tested(scene, triangle)) return false;
  const float centre = base_color_alpha(scene, triangle, bary.y, bary.z);
  float shift = 0.0f;
  for (const auto& k : kShiftSigns) {
    const glm::dvec2 d = reach * (double(k[0]) * db_dx + double(k[1]) * db_dy);
    const float a = base_color_alpha(scene, triangle, bary.y + float(d.x), bary.z + float(d.y));
    shift = std::max(shift, std::abs(a - centre));
  }
  return near_cutoff(scene, triangle, centre, kAlphaWeightSlack + shift);
}

}  // namespace vct
