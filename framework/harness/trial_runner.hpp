#pragma once
// Runs one seeded trial of one algorithm. Never throws: an optimizer that
// throws, or a trial in which no candidate had a finite fitness, gives a
// failed trial carrying the message, and the campaign goes on.
#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

// `evaluation_threads`: threads each batch evaluation may use (see
// thread_split.hpp); the result does not depend on it.
TrialResult run_trial(const Problem& problem, const Experiment& experiment, int algorithm_index,
                      long trial, int evaluation_threads = 1);

}  // namespace hystbench
