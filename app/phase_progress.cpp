#include "phase_progress.h"

#include <cstdio>

namespace vct::app {

PhaseProgress::PhaseProgress(bool enabled, std::string command, int total_phases)
    : enabled_(enabled), command_(std::move(command)), total_(total_phases) {}

PhaseProgress::~PhaseProgress() { end(); }

void PhaseProgress::begin(const std::string& phase) {
  end();
  ++done_;
  if (!enabled_) return;
  // "\r\033[K": back to the line start and erase it (ECMA-48 EL), so one line shows the phase.
  std::fprintf(stderr, "\r\033[K%s [%d/%d] %s ...", command_.c_str(), done_, total_ < done_ ? done_ : total_,
               phase.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void PhaseProgress::end() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace vct::app
