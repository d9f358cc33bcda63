#include "compare/metamorphic_bounds.h"

#include <cmath>

#include "compare/tolerance.h"
#include "shared/voxel_fixed_point.h"

namespace vct::cmp {

double storage_rounding(const VctSettings& s, double v) {
  return s.storage == VoxelStorage::Rgba8 ? 1.0 / 255.0 : half_ulp(v);
}

double doubled_voxel_bound(const VctSettings& s, double v, double n) {
  double reduction = 0.0;
  if (s.reduction == Reduction::FixedPoint) reduction = 2.0 * double(sh::FIXED_POINT_INV_SCALE);
  if (s.reduction == Reduction::CasRgba8) reduction = n / 255.0;
  if (s.storage == VoxelStorage::Rgba8) return reduction + 1.0 / 255.0;
  return reduction > 0.0 ? reduction + half_ulp(v) : 0.0;
}

double next_level_bound(const VctSettings& s, double below, double vmax) {
  const double b = below * (s.anisotropic ? 2.0 : 1.0);
  if (s.storage == VoxelStorage::Rgba8) return b + 1.0 / 255.0;
  return b > 0.0 ? b + half_ulp(vmax) : b;
}

double max_cone_steps(const VctSettings& s) {
  return std::ceil(double(s.max_distance) * double(s.grid) / double(s.cone_quality)) + 1.0;
}

double diffuse_weight_sum(const VctSettings& s) {
  return s.diffuse_weighting == DiffuseWeighting::SeedSum ? double(s.diffuse_cone_count) : 1.0;
}

}  // namespace vct::cmp
