// A one-line progress bar with rate and ETA on stderr for long renders. Silent unless enabled
// (the caller enables it only when stderr is a terminal), so logs and tests stay clean.
#pragma once

#include <chrono>
#include <cstdint>

namespace vct::pt {

class ProgressBar {
 public:
  ProgressBar(bool enabled, uint32_t start, uint32_t target);
  /// `done` passes finished, `rays` traced since the start.
  void update(uint32_t done, uint64_t rays);
  /// Ends the line (if anything was drawn).
  void finish();

  static bool stderr_is_terminal();

 private:
  bool enabled_;
  bool drawn_ = false;
  uint32_t start_, target_;
  std::chrono::steady_clock::time_point t0_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace vct::pt
