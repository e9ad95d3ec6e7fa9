#pragma once
// One self-rewriting status line on a terminal (trials done, best so far,
// elapsed, ETA); silent when stderr is not a terminal, so logs stay clean.
#include <chrono>
#include <string>

#include "framework/harness/trial_result.hpp"

namespace hystbench {

class Progress {
 public:
  Progress(long total_trials, bool enabled);
  void trial_done(const TrialResult& r);
  void finish();

 private:
  long total_;
  long done_ = 0;
  bool enabled_;
  double best_;
  std::string best_label_;
  std::chrono::steady_clock::time_point start_;
};

// True when stderr is an interactive terminal.
bool stderr_is_terminal();

}  // namespace hystbench
