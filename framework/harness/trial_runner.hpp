#pragma once
// Runs one seeded trial of one algorithm. Never throws: an optimizer that
// throws, or a trial in which no candidate had a finite fitness, gives a
// failed trial carrying the message, and the campaign goes on.
#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

TrialResult run_trial(const Problem& problem, const Experiment& experiment, int algorithm_index,
                      long trial);

}  // namespace hystbench
