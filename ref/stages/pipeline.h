// The whole CPU VCT frame, stage after stage, with per-stage timings (docs/pipeline.md):
// shadow maps -> G-buffer -> voxelization -> injection + reduction (+ multibounce, particles)
// -> mips -> direct (PCF or cone shadows) -> indirect cones -> particles -> composite.
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/raster.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// The cone-traced tail of a frame, on whatever G-buffer and mips `r` holds (its own, or a test
/// renderer's: compare/isolated_stages.h): soft-shadowed direct light when soft_shadows is on,
/// the indirect cones, then the composite. r.images.direct (PCF) and r.images.particles are its
/// inputs otherwise. Records "direct_soft_shadows", "indirect_cones", "composite" timings.
/// `march_end`: the indirect cones' MarchParams::march_end (the march-end tie's alternatives).
void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, int march_end = 0);

/// Same, tracing in `mips` (another frame's, read in place) instead of r.mips: a re-trace on a test
/// frame's inputs then copies no volume (256^3: ~300 MB; docs/performance.md, "Validate at grid 256").
void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, const VoxelMips& mips,
                       int march_end = 0);

/// What a frame computed on its way that its outputs do not keep, for the judge's freedoms
/// (freedoms/reference_freedoms.h), which start from the same raster and fragments.
struct FrameIntermediates {
  VisibilityBuffer camera;              // the G-buffer's raster (render_gbuffer's visibility)
  Voxelization voxels;                  // the voxelization the frame injected
  std::vector<vec3> fragment_light;     // the last frame's light per fragment (order of voxels.fragments)
};

/// A frame of the CPU VCT stages and what they left on the way.
struct VctFrame {
  FrameResult result;
  FrameIntermediates intermediates;
};

/// Runs every VCT stage of the CPU reference, nothing of the judge's (the whole reference frame
/// is freedoms/reference_frame.h's render_ref_frame). The voxelizer samples at `sample_positions`
/// (a driver's GL_SAMPLE_POSITION list, BackendFacts::sample_positions) instead of the standard
/// pattern of settings.vct.msaa_samples when not empty. Threads come from set_thread_count(); the
/// result is byte-identical for any thread count. The timing "total_vct" is the whole of it.
VctFrame run_vct_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions);

}  // namespace vct
