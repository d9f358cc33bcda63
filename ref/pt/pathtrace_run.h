// `vct pathtrace` without the command line: resume from a compatible checkpoint in the run
// directory, render the missing passes with periodic checkpoints, write the AOVs (+ variance)
// and run.json. Tests call this directly.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "core/settings.h"
#include "pt/integrator.h"
#include "scene/scene.h"

namespace vct::pt {

constexpr const char* kCheckpointFile = "pt_checkpoint.bin";

struct PathtraceRunOptions {
  std::string out_dir;
  bool progress = false;                 // progress bar on stderr
  std::function<bool()> stop_requested;  // polled after each pass (e.g. SIGINT); may be empty
  bool write_images = true;
};

struct PathtraceRunResult {
  uint32_t spp = 0;           // passes in the final accumulators
  uint32_t resumed_from = 0;  // passes found in a compatible checkpoint (0 = fresh start)
  std::string checkpoint_note;  // why an existing checkpoint was not used (empty if none/used)
  bool completed = false;     // false if stopped before reaching settings.pt.spp
  RayCounts rays;             // rays traced by this run (not by the resumed part)
  double render_seconds = 0.0;
};

PathtraceRunResult run_pathtrace(const Scene& scene, const Settings& settings, const PathtraceRunOptions& opt);

}  // namespace vct::pt
