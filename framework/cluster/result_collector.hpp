#pragma once
// Puts the finished trials of every rank back in (algorithm, trial) order, as
// run_campaign returns them, and passes each to the run's callback (the
// trials.jsonl line, the progress line) one at a time, as it arrives.
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "framework/harness/trial_range.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench::cluster {

class ResultCollector {
 public:
  ResultCollector(int algorithms, TrialRange trials,
                  std::function<void(const TrialResult&)> on_trial_done);
  // Thread-safe. Never throws: a result that does not belong to the campaign,
  // or a callback that throws, is kept as the run's error (the first one).
  void add(TrialResult r);
  // A trial finished by an earlier run (`run --resume`): into the results,
  // not to the callback (its line is in trials.jsonl already).
  void keep(TrialResult r);
  // Keeps `error` as the run's error unless one is kept already.
  void fail(std::exception_ptr error);
  bool failed();
  // The results; rethrows the first error.
  std::vector<std::vector<TrialResult>> take_results();

 private:
  void place(TrialResult r, bool report);

  std::mutex mutex_;
  TrialRange trials_;
  std::function<void(const TrialResult&)> on_trial_done_;
  std::vector<std::vector<TrialResult>> results_;
  std::vector<std::vector<bool>> present_;
  std::exception_ptr error_;
};

}  // namespace hystbench::cluster
