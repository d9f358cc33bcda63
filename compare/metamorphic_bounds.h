// The rounding bounds the metamorphic relations share (docs/metamorphic.md derives each): what
// storage and the reduction may add per voxel, per mip level, per cone.
#pragma once

#include "core/settings.h"

namespace vct::cmp {

/// Rounding of one stored voxel value v: 1/255 (RGBA8) or one half-float ulp of v (RGBA16F: two
/// roundings of nearby values, each <= half an ulp).
double storage_rounding(const VctSettings& s, double v);

/// Doubling: how far a doubled voxel (expected value v, n fragments) may be from twice the base
/// voxel. Fixed point: floor(2y + 1/2) and 2 floor(y + 1/2) differ by <= 1 per fragment, so the
/// sums by <= n and the rounded means by <= 2 quanta (2^-13); CAS: <= 1/255 per running-average
/// step; then storage (RGBA8 always: round(2y) != 2 round(y); half only when the values differ).
double doubled_voxel_bound(const VctSettings& s, double v, double n);

/// One more mip level over a bound `below`: the box filter keeps an absolute bound, anisotropic
/// compositing (front + (1 - a) back) at most doubles it, storage rounds once more (values up to
/// vmax) unless nothing differs yet (`below` = 0 and half storage: rounding commutes).
double next_level_bound(const VctSettings& s, double below, double vmax);

/// Samples one cone takes at most: its step is >= quality x one voxel (1/N in texture units) over
/// at most max_distance.
double max_cone_steps(const VctSettings& s);

/// Sum of the diffuse cone weights: 1 when normalised (cosine), the cone count for the seed's sum.
double diffuse_weight_sum(const VctSettings& s);

}  // namespace vct::cmp
