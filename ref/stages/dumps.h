// The one dump writer both backends use, so ref and gl run directories hold the same file names
// (listed in docs/pipeline.md, "Dump files"). Only what the FrameResult holds is written.
#pragma once

#include "core/settings.h"
#include "io/run_dir.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// Writes every stage output present in `frame` (images EXR + PNG, volumes NRRD + PNG montage),
/// records frame.timings_ms under run.json["timings_ms"][frame.backend], frame.info under
/// run.json["info"][frame.backend], the multibounce energies, and saves run.json.
void write_frame_dumps(RunDir& dir, const FrameResult& frame, const Scene& scene, const VctSettings& settings);

}  // namespace vct
