// The one per-element measure every judge uses: over an element's channels, the worst ratio of the
// distance to the admissible value (|test - ref|, or to an interval) over the element's bound.
#pragma once

#include <algorithm>
#include <cmath>

namespace vct::cmp {

struct ChannelDistance {
  double distance = 0.0;  // how far the test value lies outside what the bound admits around ref
  double bound = 0.0;     // the bound that applied
  double shown = 0.0;     // |test - ref|, as the offender list shows it
};

struct WorstChannel {
  double ratio = 0.0;  // > 1: beyond the bound (non-finite values count as infinitely far)
  float error = 0.0f, bound = 0.0f;
  bool within() const { return ratio <= 1.0; }
};

/// `measure(c)` gives channel c's ChannelDistance. A zero bound admits only a zero distance.
template <typename Measure>
WorstChannel worst_channel(int channels, Measure measure) {
  WorstChannel w;
  for (int c = 0; c < channels; ++c) {
    const ChannelDistance d = measure(c);
    const double ratio = !std::isfinite(d.distance) ? 1e30
                         : d.bound > 0          ? d.distance / d.bound
                                                : (d.distance > 0 ? 1e30 : 0.0);
    if (c == 0 || ratio > w.ratio) w.ratio = ratio, w.error = float(d.shown), w.bound = float(d.bound);
  }
  return w;
}

}  // namespace vct::cmp
