#pragma once
// COCO-style runtime measures of one algorithm from its trials (Hansen,
// Auger, Brockhoff, Tusar, Tusar, "COCO: Performance assessment",
// arXiv:1605.03560, 2016): success rate, expected running time (ERT, called
// aRT since 2016), the empirical CDF of runtimes, and fixed-budget
// snapshots of the best-so-far value.
//
// Runtime of trial r to target f_t, counted in evaluations:
//   RT_r = evaluations at which r first reached best <= f_t   (success)
//        = all evaluations r spent                             (failure)
//   ERT  = sum_r RT_r / #successes         (+inf without a success)
// Lower values are better (minimisation).
#include <optional>
#include <vector>

#include "framework/core/evaluation_context.hpp"

namespace hystbench::stats {

// What a trial leaves for these measures: TrialResult::evaluations and
// TrialResult::trace. The trace holds best-so-far improvements in
// increasing evaluation order, as EvaluationContext::trace() records them.
// Which trials count (e.g. whether a crashed one does) is the caller's call.
struct TrialRecord {
  long evaluations = 0;
  std::vector<TracePoint> trace;
};

// Evaluations at the first trace point with best <= target; nullopt if the
// trace never gets there. InputError for a NaN target.
std::optional<long> evaluations_to_target(const std::vector<TracePoint>& trace, double target);

// RT of one trial. A failed trial's cost is its evaluation count, or the
// last trace point's if that is later (the trace is never cut short).
long runtime_to_target(const TrialRecord& trial, double target);

// Fraction of trials that reach the target. InputError without trials.
double success_rate(const std::vector<TrialRecord>& trials, double target);

// ERT; +inf when no trial reaches the target. InputError without trials.
double expected_runtime(const std::vector<TrialRecord>& trials, double target);

// One step of a runtime ECDF: the fraction of (trial, target) pairs solved
// within `evaluations`.
struct EcdfStep {
  long evaluations = 0;
  double fraction = 0.0;
};

// Steps of the ECDF over all (trial, target) pairs, at each distinct
// success runtime in increasing order (a run that never succeeds adds to
// the denominator only, so the curve may end below 1). Empty without a
// success. InputError without trials or targets.
std::vector<EcdfStep> runtime_ecdf(const std::vector<TrialRecord>& trials,
                                   const std::vector<double>& targets);
std::vector<EcdfStep> runtime_ecdf(const std::vector<TrialRecord>& trials, double target);

// Best-so-far value after `evaluations`: the last trace point at or before
// it; +inf when the trace has none yet.
double best_at(const std::vector<TracePoint>& trace, long evaluations);

// best_at(trace, floor(fraction * budget)) for each fraction (e.g. 0.1,
// 0.5, 1.0), with fraction * budget rounded so that 0.57 * 100 counts as
// 57. InputError for budget < 1 or a fraction that is
// negative, infinite or NaN.
std::vector<double> fixed_budget_snapshots(const std::vector<TracePoint>& trace, long budget,
                                           const std::vector<double>& fractions);

}  // namespace hystbench::stats
