// Raster alternatives in the comparison: the reference's GBuffer::tie_range (stages/gbuffer_ties.h)
// holds, per G-buffer stage and channel, the range of its own value and of every value a correct
// GL may show where an edge or a triangle's facing ties under vertex snapping. A beyond-bound
// pixel inside that range (plus the pixel's bound) is a value a correct GL gives there: admitted,
// whatever the count, and reported (docs/compare.md, "Raster alternatives").
#pragma once

#include <string>
#include <vector>

#include "core/image.h"

namespace vct::cmp {

/// Channels of `range` holding `stage`'s lower and upper ends, channel by channel (lo[c], hi[c]
/// for c < channels); empty when `stage` is not a G-buffer stage the range covers (nor
/// image.direct / image.emission, whose ranges the reference computes on the test's own inputs,
/// stages/direct_ties.h) or the image lacks one of them.
struct TieRangeChannels {
  std::vector<int> lo, hi;
  bool empty() const { return lo.empty(); }
};
TieRangeChannels tie_range_channels(const std::string& stage, const Image& range, int channels);

/// True when channel c of the test pixel lies in [lo - bound, hi + bound] at (x, y).
bool within_tie_range(const Image& range, const TieRangeChannels& ch, int x, int y, int c, double test,
                      double bound);

}  // namespace vct::cmp
