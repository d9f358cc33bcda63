#include "compare/metamorphic_bounds.h"

#include "compare/tolerance.h"
#include "core/declared_cones.h"
#include "shared/voxel_fixed_point.h"

namespace vct::cmp {

namespace {
const double kHalfRel = std::ldexp(1.0, -10);        // one binary16 ulp relative to a normal value
const double kHalfSubnormal = std::ldexp(1.0, -24);  // binary16 spacing below 2^-14
}  // namespace

double storage_rounding(const VctSettings& s, double v) {
  return s.storage == VoxelStorage::Rgba8 ? 1.0 / 255.0 : half_ulp(v);
}

LinearBound doubled_voxel_bound(const VctSettings& s, double n, int particles) {
  LinearBound b;
  if (s.reduction == Reduction::FixedPoint) b.abs = 2.0 * double(sh::FIXED_POINT_INV_SCALE);
  if (s.reduction == Reduction::CasRgba8) b.abs = n / 255.0;
  b.abs += double(particles) * double(sh::FIXED_POINT_INV_SCALE);
  if (s.storage == VoxelStorage::Rgba8) {
    b.abs += 1.0 / 255.0;
    return b;
  }
  if (b.abs > 0.0) b.rel = kHalfRel;
  b.abs += kHalfSubnormal;
  return b;
}

LinearBound next_level_bound(const VctSettings& s, const LinearBound& below) {
  LinearBound b{below.abs * (s.anisotropic ? 2.0 : 1.0), below.rel};
  if (s.storage == VoxelStorage::Rgba8) {
    b.abs += 1.0 / 255.0;
    return b;
  }
  if (!below.zero()) b.rel += kHalfRel;
  b.abs += kHalfSubnormal;
  return b;
}

double max_cone_steps(const VctSettings& s) {
  return std::ceil(double(s.max_distance) * double(s.grid) / double(s.cone_quality)) + 1.0;
}

double diffuse_weight_sum(const VctSettings& s) {
  // An engine's declared set (core/declared_cones.h) weighs its cones as it says.
  const std::vector<DeclaredCone> declared = parse_declared_cones(s.diffuse_cone_set);
  if (!declared.empty()) {
    double sum = 0.0;
    for (const DeclaredCone& c : declared) sum += double(c.weight);
    return sum;
  }
  return s.diffuse_weighting == DiffuseWeighting::SeedSum ? double(s.diffuse_cone_count) : 1.0;
}

}  // namespace vct::cmp
