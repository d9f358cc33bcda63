#include "pt/progress.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace vct::pt {

namespace {
std::string format_duration(double s) {
  const long t = long(s + 0.5);
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm%02lds", t / 3600, (t / 60) % 60, t % 60);
  else if (t >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}
}  // namespace

ProgressBar::ProgressBar(bool enabled, uint32_t start, uint32_t target)
    : enabled_(enabled), start_(start), target_(target), t0_(std::chrono::steady_clock::now()), last_draw_(t0_) {}

bool ProgressBar::stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

void ProgressBar::update(uint32_t done, uint64_t rays) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // Redraw at most 10 times a second, and always at the end.
  if (done < target_ && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - t0_).count();
  const uint32_t new_passes = done - start_;
  const double spp_rate = elapsed > 0.0 ? new_passes / elapsed : 0.0;
  const double eta = spp_rate > 0.0 ? (target_ - done) / spp_rate : 0.0;
  constexpr int kWidth = 30;
  const int filled = target_ > 0 ? int(double(done) / target_ * kWidth) : kWidth;
  std::string bar(size_t(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\rpathtrace [%s] %u/%u spp  %.2f spp/s  %.2f Mrays/s  ETA %s   ", bar.c_str(), done,
               target_, spp_rate, elapsed > 0.0 ? double(rays) / elapsed * 1e-6 : 0.0,
               format_duration(eta).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace vct::pt
