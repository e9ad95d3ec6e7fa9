#pragma once
// Runs every (algorithm, trial) pair of an experiment, in parallel.
#include <functional>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

struct CampaignOptions {
  int threads = 1;
  // Called once per finished trial, one call at a time, in finishing order
  // (which varies with threads; nothing numeric may depend on it).
  std::function<void(const TrialResult&)> on_trial_done;
  // Which trials to run; all of them when empty (size 0).
  TrialRange trials;
  // Trials finished by an earlier run of the same campaign (--resume): put
  // into the results as they are, not run again, not reported again.
  std::vector<TrialResult> finished;
};

// Results grouped per algorithm, each group in trial order (only the trials
// of options.trials when it is set): independent of
// thread count and scheduling because every trial has its own derived seed.
std::vector<std::vector<TrialResult>> run_campaign(const Problem& problem,
                                                   const Experiment& experiment,
                                                   const CampaignOptions& options);

}  // namespace hystbench
