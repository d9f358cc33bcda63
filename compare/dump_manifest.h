// The manifest of a `vct render --dump` run directory: vct-stages.json beside the dumped files, so
// a dumped run is a stage set `vct compare` reads (docs/external_format.md) without writing every
// stage a second time.
#pragma once

#include <string>

#include "core/settings.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// Sub-folder of a dumped run that holds the stages the dump has no file for (and its own
/// manifest, so it is a stage set too).
inline constexpr const char* kUndumpedStagesDir = "stage_files";

/// Writes `dir`/vct-stages.json listing every stage of stage_set_from_frame(f, s): a stage the dump
/// wrote as the frame's own data points at the dump's file (ref/stages/dumps.h, the registry's dump
/// stems); any other stage is written under kUndumpedStagesDir. Call after write_frame_dumps.
void write_dump_manifest(const std::string& dir, const FrameResult& f, const VctSettings& s);

}  // namespace vct::cmp
