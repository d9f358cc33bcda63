// Raster alternatives in the comparison: the reference's GBuffer::tie_range (freedoms/gbuffer_ties.h)
// holds, per G-buffer stage and channel, the range of its own value and of every value a correct
// GL may show where an edge or a triangle's facing ties under vertex snapping; ShadowMap::tie_range
// and cube_tie_range (freedoms/shadow_map_ties.h) the same for each shadow-map texel's depth. A beyond-bound
// pixel inside that range (plus the pixel's bound) is a value a correct GL gives there: admitted,
// whatever the count, and reported (docs/compare.md, "Raster alternatives").
#pragma once

#include <string>
#include <vector>

#include "core/image.h"

namespace vct::cmp {

/// The reference-only stage holding `stage`'s range: shadow_map_tie_range.N for shadow_map.N,
/// shadow_map_cube_tie_range.N for shadow_map_cube.N (freedoms/shadow_map_ties.h), gbuffer.tie_range
/// for every other stage (the G-buffer's, and image.direct / image.emission on the test's own inputs).
std::string tie_range_stage(const std::string& stage);

/// Channels of `range` holding `stage`'s lower and upper ends, channel by channel (lo[c], hi[c]
/// for c < channels); empty when `stage` is not a G-buffer stage the range covers (nor
/// image.direct / image.emission, whose ranges the reference computes on the test's own inputs,
/// freedoms/direct_ties.h, nor a shadow map, whose range is its "depth" group) or the image lacks
/// one of them.
struct TieRangeChannels {
  std::vector<int> lo, hi;
  bool empty() const { return lo.empty(); }
};
TieRangeChannels tie_range_channels(const std::string& stage, const Image& range, int channels);

/// `range` without the channels of `group` (e.g. "image.direct"): a stage whose range the reference
/// cannot derive on the inputs at hand then has no range rule, and admits nothing by it.
Image without_tie_range_group(const Image& range, const std::string& group);

/// True when channel c of the test pixel lies in [lo - bound, hi + bound] at (x, y).
bool within_tie_range(const Image& range, const TieRangeChannels& ch, int x, int y, int c, double test,
                      double bound);

}  // namespace vct::cmp
