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
// Refuses (InputError naming the key) a Levenberg-Marquardt polish on a
// problem that is not a least-squares problem: checked before a run starts.
void check_polish(const Experiment& experiment, const Problem& problem);
// The problem's residuals; throws InputError when it has none.
const LeastSquaresProblem& least_squares_of(const Problem& problem);

TrialResult run_trial(const Problem& problem, const Experiment& experiment, int algorithm_index,
                      long trial, int evaluation_threads = 1);

}  // namespace hystbench
