// The whole CPU VCT frame, stage after stage, with per-stage timings (docs/pipeline.md):
// shadow maps -> G-buffer -> voxelization -> injection + reduction (+ multibounce, particles)
// -> mips -> direct (PCF or cone shadows) -> indirect cones -> particles -> composite.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// The cone-traced tail of a frame, on whatever G-buffer and mips `r` holds (its own, or a test
/// renderer's: compare/isolated_stages.h): soft-shadowed direct light when soft_shadows is on,
/// the indirect cones, then the composite. r.images.direct (PCF) and r.images.particles are its
/// inputs otherwise. Records "direct_soft_shadows", "indirect_cones", "composite" timings.
/// `march_end`: the indirect cones' MarchParams::march_end (the march-end tie's alternatives).
void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, int march_end = 0);

/// The reference's own work for the judge, which a VCT frame does not do (raster alternatives,
/// slacks, coverage ties, the holes map, the running mean's interval), by timing name: `vct bench`
/// counts them apart from the stages (compare/stage_timings.cpp), and the timing "total_vct" is
/// "total" without them.
inline constexpr const char* kOracleExtraStages[] = {"gbuffer_ties", "shadow_tie_ranges", "direct_slack",
                                                     "voxel_slack",  "coverage_ties",     "holes",
                                                     "running_mean_interval"};

/// Runs every stage of the CPU reference. Threads come from set_thread_count(); the result is
/// byte-identical for any thread count.
FrameResult render_ref_frame(const Scene& scene, const Settings& settings);

/// Same, with the GPU-rule voxelizer sampling at `sample_positions` (a driver's
/// GL_SAMPLE_POSITION list, BackendFacts::sample_positions) instead of the standard pattern of
/// settings.vct.msaa_samples; empty = the standard pattern.
FrameResult render_ref_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions);

}  // namespace vct
