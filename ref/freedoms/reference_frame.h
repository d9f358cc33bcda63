// The reference frame the judge reads: the CPU VCT stages (stages/pipeline.h), then the oracle's
// freedoms beside them (freedoms/reference_freedoms.h). Timings: "total_vct" for the stages,
// "total_oracle" for the freedoms, "total" for both.
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// Every stage of the CPU reference and every freedom beside it. Threads come from
/// set_thread_count(); the result is byte-identical for any thread count.
FrameResult render_ref_frame(const Scene& scene, const Settings& settings);

/// Same, with the GPU-rule voxelizer sampling at `sample_positions` (a driver's
/// GL_SAMPLE_POSITION list, BackendFacts::sample_positions) instead of the standard pattern of
/// settings.vct.msaa_samples; empty = the standard pattern.
FrameResult render_ref_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions);

}  // namespace vct
