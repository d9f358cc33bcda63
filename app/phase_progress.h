// Per-phase progress of long commands (vct validate and its sweeps) on stderr: one line, rewritten
// in place, naming the phase that runs now and how far the command is ("validate [3/8] path
// tracer, 64 spp"). Only while a terminal watches (the caller passes stderr_is_terminal()), so
// logs, pipes and tests stay clean; ref/pt/progress.h is the model (and draws the path tracer's
// passes inside its phase).
#pragma once

#include <chrono>
#include <string>

namespace vct::app {

class PhaseProgress {
 public:
  PhaseProgress(bool enabled, std::string command, int total_phases);
  ~PhaseProgress();
  /// Clears the previous phase's line and shows this one as phase k+1 of the total.
  void begin(const std::string& phase);
  /// Clears the line (the command then prints its result for the phase on stdout).
  void end();
  /// More phases than planned (e.g. a sweep's values once parsed).
  void add_phases(int n) { total_ += n; }
  bool enabled() const { return enabled_; }

 private:
  bool enabled_;
  std::string command_;
  int total_, done_ = 0;
  bool drawn_ = false;
};

}  // namespace vct::app
