// `vct_gl_runner --timings 32,64,128,256`: GPU time per stage (timer queries, gl/gl_timer.h) for
// each grid size, isotropic and anisotropic, with and without the depth pre-pass: the source
// design's performance tables, measured on the device. Best of --repeat runs after one warm-up.
#pragma once

#include "runner_options.h"

namespace vct::gl {

/// Renders the sweep on one context, prints the table, writes OUT/timings.json; returns 0.
int run_timings(const RunnerOptions& o);

}  // namespace vct::gl
