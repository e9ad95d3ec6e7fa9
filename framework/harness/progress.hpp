#pragma once
// The progress of a campaign of trials (trials done, best so far, ETA),
// shown by the shared StatusLine: a terminal line, timestamped log lines, or
// nothing with --quiet.
#include <string>

#include "framework/harness/status_line.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

class Progress {
 public:
  explicit Progress(long total_trials, ProgressMode mode = progress_mode());
  void trial_done(const TrialResult& r);
  void finish();

 private:
  long total_;
  long done_ = 0;
  double best_;
  std::string best_label_;
  std::chrono::steady_clock::time_point start_;
  StatusLine line_;
};

}  // namespace hystbench
