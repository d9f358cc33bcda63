// The dump writer of `vct render --dump` (file names: the stage registry's dump stems, listed in
// docs/pipeline.md, "Dump files"), and the per-stage file writer it shares with stage sets
// (compare/stage_set.cpp), so a stage's preview looks the same wherever it is written. Only what
// the FrameResult holds is written.
#pragma once

#include "core/settings.h"
#include "io/run_dir.h"
#include "scene/scene.h"
#include "stages/stage_registry.h"
#include "stages/stage_types.h"

namespace vct {

/// Writes `stem`.exr and a PNG preview mapped as the row says. Preview::Position maps
/// [position_lo, position_hi] to grey (the caller knows the scene's extent, or takes the data's).
void write_stage_image(RunDir& dir, const std::string& stem, const StageRow& row, const Image& img,
                       float position_lo = 0.0f, float position_hi = 1.0f);

/// Writes every stage output present in `frame` (images EXR + PNG, volumes NRRD + PNG montage),
/// records frame.timings_ms under run.json["timings_ms"][frame.backend], frame.info under
/// run.json["info"][frame.backend], the multibounce energies, and saves run.json.
void write_frame_dumps(RunDir& dir, const FrameResult& frame, const Scene& scene);

}  // namespace vct
