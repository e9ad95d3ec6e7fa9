#include "framework/harness/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <limits>

namespace hystbench {

bool stderr_is_terminal() { return isatty(fileno(stderr)) != 0; }

Progress::Progress(long total_trials, bool enabled)
    : total_(total_trials),
      enabled_(enabled),
      best_(std::numeric_limits<double>::infinity()),
      start_(std::chrono::steady_clock::now()) {}

void Progress::trial_done(const TrialResult& r) {
  ++done_;
  if (!r.failed() && r.best < best_) {
    best_ = r.best;
    best_label_ = r.label;
  }
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = elapsed / double(done_) * double(total_ - done_);
  std::fprintf(stderr, "\r  trials %ld/%ld   best %.6g (%s)   elapsed %.0f s   ETA %.0f s   ", done_,
               total_, best_, best_label_.c_str(), elapsed, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (enabled_ && done_ > 0) std::fprintf(stderr, "\n");
}

}  // namespace hystbench
