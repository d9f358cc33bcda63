// The rounding bounds the metamorphic relations share (docs/metamorphic.md derives each): what
// storage and the reduction may add per voxel, per mip level, per cone.
#pragma once

#include <cmath>

#include "core/settings.h"

namespace vct::cmp {

/// |difference| <= abs + rel x |value|.
struct LinearBound {
  double abs = 0.0, rel = 0.0;
  double at(double v) const { return abs + rel * std::abs(v); }
  bool zero() const { return abs == 0.0 && rel == 0.0; }
};

/// Rounding of one stored voxel value v: 1/255 (RGBA8) or one half-float ulp of v (RGBA16F: two
/// roundings of nearby values, each <= half an ulp).
double storage_rounding(const VctSettings& s, double v);

/// Doubling: how far a doubled voxel (from n fragments) may be from twice the base voxel.
/// Fixed point: floor(2y + 1/2) and 2 floor(y + 1/2) differ by <= 1 per fragment, so the sums by
/// <= n and the rounded means by <= 2 quanta (abs 2^-13); CAS: <= 1/255 per running-average step
/// (abs n/255); storage: RGBA8 always abs 1/255 (round(2y) != 2 round(y)); half floats commute
/// with doubling but for values that already differ (rel 2^-10: one ulp) and subnormals (below
/// 2^-14 the spacing is fixed: abs 2^-24). Particle light is added, not averaged; a backend may
/// add each of the scene's `particles` in fixed point (the GL build does: docs/gl_backend.md), each
/// <= 1 quantum apart: abs particles x 2^-14, then stored once more (rel 2^-10).
LinearBound doubled_voxel_bound(const VctSettings& s, double n, int particles = 0);

/// One more mip level: a box filter of non-negative values keeps abs and rel, anisotropic
/// compositing (front + (1 - a) back, the same a on both sides) keeps rel and at most doubles abs;
/// storage rounds once more (RGBA8 abs 1/255; half: rel 2^-10 once anything differs, abs 2^-24
/// for subnormals).
LinearBound next_level_bound(const VctSettings& s, const LinearBound& below);

/// Samples one cone takes at most: its step is >= quality x one voxel (1/N in texture units) over
/// at most max_distance. A cone's result is sum T_i s_i with T_i <= 1, so its error is <= rel x
/// |result| + steps x abs.
double max_cone_steps(const VctSettings& s);

/// Sum of the diffuse cone weights: 1 when normalised (cosine), the cone count for the seed's sum.
double diffuse_weight_sum(const VctSettings& s);

}  // namespace vct::cmp
