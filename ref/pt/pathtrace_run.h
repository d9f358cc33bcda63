// `vct pathtrace` without the command line: resume from a compatible checkpoint in the run
// directory, render the missing passes with periodic checkpoints, write the AOVs (+ variance)
// and run.json. Tests call this directly.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "core/settings.h"
#include "pt/checkpoint.h"
#include "pt/integrator.h"
#include "pt/partial_sums.h"
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
  double render_cpu_seconds = 0.0;  // process CPU time of the passes (all threads; bench/mitsuba_compare.py)
};

/// The hashes a checkpoint or partial-sums file of this scene and these settings carries.
CheckpointKey checkpoint_key(const Scene& scene, const Settings& settings);

PathtraceRunResult run_pathtrace(const Scene& scene, const Settings& settings, const PathtraceRunOptions& opt);

/// One cluster task: samples [first, end) from zero, written to `partial_path` (docs/cluster.md).
/// The per-pixel sums are bit for bit those samples' share of a one-machine render.
PartialSums run_sample_range(const Scene& scene, const Settings& settings, uint32_t first, uint32_t end,
                             const std::string& partial_path, bool progress);

/// Merges every `*.ptpart` file of `partials_dir` in sample order into opt.out_dir as
/// run_pathtrace writes it (AOVs, variances, checkpoint, run.json); `partials_dir`/tasks.json,
/// when present, becomes run.json's pathtrace.tasks (the per-task hosts and times).
PathtraceRunResult merge_sample_ranges(const Scene& scene, const Settings& settings, const std::string& partials_dir,
                                       const PathtraceRunOptions& opt);

}  // namespace vct::pt
