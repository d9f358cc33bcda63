// The interval of every value a racy reduction may leave in a voxel (docs/compare.md,
// "cas-rgba8-interval" and "running-mean-half-interval"): the reference cannot pick the order or
// the lost updates, so it states the interval and the comparison judges the test against it.
// The reductions themselves are stages/reduction.h (CAS, with its value interval cas_interval) and
// stages/running_mean.h; this file turns them into the judge's volumes VoxelGrid::cas_lo/cas_hi.
#pragma once

#include <utility>
#include <vector>

#include "core/settings.h"
#include "core/volume.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

struct ValueInterval {
  float lo = 0.0f, hi = 0.0f;
};

/// Every value the running mean may leave, for any order and any non-empty subset of `values`
/// (lost updates), lies in [h(min) - 2 ulp, h(max) + 2 ulp] (ulp: binary16 spacing there). Why:
/// each step averages values in [min, max] (induction), and rounding is monotone, so every step
/// stays in [h(min), h(max)] when rounding to nearest; one ulp more on each side admits any
/// binary16 rounding mode (GL 4.5 §2.3.4.2 leaves it to the implementation) and one more the
/// float32 arithmetic of the average pushing a value across a rounding boundary. The singletons
/// {min} and {max} (all but one update lost) reach h(min) and h(max): the interval is tight to
/// those ulps. Empty input: {0, 0}.
ValueInterval running_mean_interval(const std::vector<float>& values);

/// Per voxel and RGB channel, running_mean_interval of the voxel's fragments (`values` in the
/// order of vox.fragments, which is sorted by voxel); alpha 1 where occupied. Written into the
/// reference's interval volumes (VoxelGrid::cas_lo / cas_hi) when it models this reduction.
void running_mean_interval_volumes(const Voxelization& vox, const std::vector<vec3>& values, Volume& lo,
                                   Volume& hi);

/// The interval after light is added to the reduced voxels (the particles' additive light,
/// stages/particles.h): each addition `add` at voxel v moves both ends by `add`, and the engine's
/// binary16 store of the sum may round either way, so each end moves one more binary16 ulp of
/// the new end outward (lo down, hi up). Additions are applied in the given order, as
/// add_particles_to_voxels applies them. A voxel with no fragments gets [add - ulp, add + ulp]
/// with alpha 0 (transparent light).
using AddedLight = std::pair<ivec3, vec3>;  // (voxel, RGB added)
void add_light_to_interval(const std::vector<AddedLight>& additions, Volume& lo, Volume& hi);

/// Per voxel and RGB channel, cas_interval (stages/reduction.h) of the voxel's fragments, as
/// running_mean_interval_volumes does for the running mean.
void cas_interval_volumes(const Voxelization& vox, const std::vector<vec3>& values, Volume& lo, Volume& hi);

/// g.cas_lo / g.cas_hi for settings.reduction (CAS or the running mean; left empty for the exact
/// reductions) from the fragments' light `values` (order of vox.fragments).
void add_reduction_interval(const Voxelization& vox, const std::vector<vec3>& values, const VctSettings& settings,
                            VoxelGrid& g);

}  // namespace vct
