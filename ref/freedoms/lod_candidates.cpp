#include "freedoms/lod_candidates.h"

#include <cmath>

namespace vct {

int lod_candidates(const LodRange& range, double out[kMaxLodCandidates]) {
  int n = 0;
  out[n++] = range.lo;
  if (range.lo <= 0.0 && range.hi > 0.0) out[n++] = 1e-9;  // minified at level 0
  for (double k = std::floor(range.lo) + 1.0; k < range.hi && n < kMaxLodCandidates - 1; k += 1.0) {
    if (k > 0.0) out[n++] = k;
  }
  if (range.hi > out[n - 1]) out[n++] = range.hi;
  return n;
}

}  // namespace vct
