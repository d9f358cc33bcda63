// vct validate's work after the renders, as independent tasks on the worker threads: the stage
// sets and the path tracer's images written, GL judged against the reference (every stage, then
// the cone stages on GL's own voxels), each backend's bias against the path tracer. Each task
// reads the frames and writes only its own files and result, so outputs and verdicts are the
// same for any thread count; the one-threaded comparison then runs beside the writes instead of
// after them (docs/performance.md, "Where validate's time goes").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/bias.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "io/run_dir.h"
#include "phase_times.h"
#include "scene/scene.h"
#include "validate_run.h"

namespace vct::app {

struct CheckResults {
  cmp::StageSet ref_set, gl_set;     // named after their run directories (ref/, gl/)
  std::optional<cmp::Report> report;  // GL vs the reference, when both frames exist
  std::vector<cmp::BiasComponent> bias_ref, bias_gl;  // empty when not measured
};

/// Runs the tasks and records each as a concurrent phase (its own wall and thread CPU time)
/// inside one counted phase for the whole group. Unless `keep_ref_frame`, the reference's frame
/// gives its stages to ref_set (moved, not copied) and its mips are freed: nothing after the
/// checks reads it then (at grid 256 that is ~1 GB less at the peak; docs/performance.md). The GL
/// frame's voxel grid moves into gl_set (cmp::stage_set_taking_voxels); the rest of it stays.
CheckResults run_checks(RunDir& run, const Scene& scene, const Settings& s, BackendRun& ref, BackendRun& gl,
                        const PtRun& pt, PhaseTimes& phases, bool keep_ref_frame);

/// Writes the path tracer's AOVs (EXR, and a PNG preview for the means) under RUN/pt.
void write_pt_images(RunDir& run, const PtRun& pt);

}  // namespace vct::app
