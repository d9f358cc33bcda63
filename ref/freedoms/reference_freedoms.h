// The oracle's own work beside a reference frame: every freedom the judge admits a test's value
// by (docs/compare.md, "The judge: one entry point, one admission table"), computed in one step
// after the VCT stages (stages/pipeline.h) from what they left, and timed as the oracle's work,
// apart from the frame's. One row per freedom, in the order they depend on each other.
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/pipeline.h"

namespace vct {

/// One freedom producer: its timing name (run.json "timings_ms", `vct bench`'s "oracle" group)
/// and what it fills in the frame.
struct FreedomStep {
  const char* timing;
  void (*add)(const Scene& scene, const VctSettings& settings, FrameIntermediates& on_the_way, FrameResult& r);
};

/// The steps, in order (the direct slack reads the texture slack; the voxel slack the coverage
/// ties).
const std::vector<FreedomStep>& freedom_steps();

/// Runs every step on `frame` (run_vct_frame's), recording each step's timing and their sum as
/// "total_oracle".
void add_reference_freedoms(const Scene& scene, const VctSettings& settings, VctFrame& frame);

}  // namespace vct
