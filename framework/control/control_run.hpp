#pragma once
// Runs every controller of an experiment over its trials (docs/control.md):
// trial t's sensor noise has the seed trial_seed(seed, "sensor noise", t),
// shared by every controller and by the uncontrolled run it is compared with,
// so the numbers depend on neither the thread count nor the order of runs.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "framework/control/control_experiment.hpp"
#include "framework/control/control_metrics.hpp"
#include "framework/control/control_setup.hpp"

namespace hystbench {

struct TrialOutcome {
  SuppressionMetrics measured, truth;  // meaningful only when the run did not diverge
  double diverged_at_s;          // NaN when it did not
};

// Mean and sample standard deviation over the trials that did not diverge.
struct MetricSummary {
  SuppressionMetrics mean, sd;
  // Trials (of those that did not diverge) whose error never settled below
  // -20 dB: their convergence time is left out of the mean.
  int never_converged = 0;
};

struct ControllerResult {
  ControllerEntry entry;
  const SecondaryPath* estimate = nullptr;  // the setup's; null for the uncontrolled runs
  std::vector<TrialOutcome> trials;
  LoopTrace first_trial;  // trial 0, for the figures
  int diverged_trials = 0;
  double earliest_divergence_s = std::numeric_limits<double>::quiet_NaN();  // when none diverged
  MetricSummary measured, truth;  // over the trials that did not diverge
  bool all_diverged() const { return diverged_trials == int(trials.size()); }
};

struct ControlResults {
  // The uncontrolled runs, measured like a controller (efficiency 0); its
  // trace is trial 0's.
  ControllerResult uncontrolled;
  std::vector<ControllerResult> controllers;
};

// `progress(done, total)` is called after each run, from any thread.
ControlResults run_control(const ControlExperiment& x, const ControlSetup& setup,
                           const std::function<void(int, int)>& progress);

}  // namespace hystbench
