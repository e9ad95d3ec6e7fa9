#include "framework/harness/progress.hpp"

#include <limits>

#include "framework/core/text.hpp"

namespace hystbench {

Progress::Progress(long total_trials, ProgressMode mode)
    : total_(total_trials),
      best_(std::numeric_limits<double>::infinity()),
      start_(std::chrono::steady_clock::now()),
      line_(mode) {}

void Progress::trial_done(const TrialResult& r) {
  ++done_;
  if (!r.failed() && r.best < best_) {
    best_ = r.best;
    best_label_ = r.label;
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = elapsed / double(done_) * double(total_ - done_);
  line_.show("trials " + std::to_string(done_) + "/" + std::to_string(total_) + "   best " +
             format_number("%.6g", best_) + " (" + best_label_ + ")   ETA " +
             format_number("%.0f", eta) + " s");
}

void Progress::finish() { line_.finish(); }

}  // namespace hystbench
