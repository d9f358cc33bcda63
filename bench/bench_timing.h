// Timing helpers shared by the benchmarks (bench/*.cpp are one program each).
#pragma once

#include <algorithm>

#include "io/run_dir.h"

namespace vct::bench {

/// Best of `repeat` runs of f, in ms: on a shared machine the least disturbed run is the one
/// closest to the work's own cost.
template <class F>
double best_ms(int repeat, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    Stopwatch w;
    f();
    best = std::min(best, w.ms());
  }
  return best;
}

}  // namespace vct::bench
