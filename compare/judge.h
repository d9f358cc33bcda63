// The judge's one entry point: every pass, in one defined order, for every caller (vct validate,
// its sweep, vct compare with and without --scene, scripts/gpu_check.sh judge through vct compare,
// Python's vct.compare). docs/compare.md, "The judge".
//   1. every stage by its admission rules (compare_stage_sets, compare/admission.h);
//   2. a conservative voxelization mode judged as a superset of the exact set (test facts say so);
//   3. with a scene, the test's frame and its settings: the cone-traced and shading stages (and
//      voxel.radiance where ties need it) re-judged on the test's own inputs;
//   4. the driver's facts noted in the verdicts they bear on.
#pragma once

#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// What the later passes need besides the two sets; each optional. Pass 3 runs only with all three.
struct JudgeInputs {
  const Scene* scene = nullptr;
  const FrameResult* test_frame = nullptr;  // the frame behind the test set (stage_set_frame.h for a set on disk)
  const VctSettings* settings = nullptr;    // the settings the test ran with
};

Report judge(const StageSet& reference, const StageSet& test, const JudgeInputs& in = {},
             const CompareOptions& opt = {});

/// True when pass 3 ran (the inputs were complete).
bool judges_on_own_inputs(const JudgeInputs& in);

}  // namespace vct::cmp
