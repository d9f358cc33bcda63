// The LOD values whose lookups span every result an admissible lambda range can give
// (stages/uv_derivatives.h makes the range; docs/compare.md, "Texture LOD"): a trilinear lookup is
// linear in lambda between integer levels (piecewise constant for *_MIPMAP_NEAREST, stepping at
// k + 1/2), so the ends and each integer between them suffice, as in dEQP's lookup verifier.
#pragma once

#include "scene/texture_lod.h"

namespace vct {

/// The lambdas whose lookups span every value an admissible lambda in `range` can give: lo, hi,
/// each integer strictly between, and (when magnification and minification both lie in the
/// range) the minified lookup at lambda -> 0+, which differs from the magnified one when the
/// filters do. At most kMaxLodCandidates (the range is then clipped to its first ones; ranges
/// are a few tenths of a level wide).
constexpr int kMaxLodCandidates = 8;
int lod_candidates(const LodRange& range, double out[kMaxLodCandidates]);

}  // namespace vct
