#include "framework/stats/runtime_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.hpp"

namespace hystbench::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check_trials(const std::vector<TrialRecord>& trials, const char* what) {
  if (trials.empty()) throw InputError(std::string(what) + ": no trials");
}

void check_target(double target) {
  if (std::isnan(target)) throw InputError("runtime measures: the target is NaN");
}

long trial_cost(const TrialRecord& trial) {
  const long traced = trial.trace.empty() ? 0 : trial.trace.back().evaluations;
  return std::max(trial.evaluations, traced);
}

// Evaluations allowed by fraction * budget. The product of a decimal
// fraction and an integer budget can fall just below the integer it means
// (0.57 * 100 = 56.999...), which would drop that evaluation's point.
long evaluations_at_fraction(double fraction, long budget) {
  if (!(fraction >= 0) || std::isinf(fraction))
    throw InputError("fixed-budget snapshot: fraction " + std::to_string(fraction) +
                     " must be a finite number >= 0");
  const double product = fraction * double(budget);
  return long(std::floor(product + 1e-9 * std::max(1.0, product)));
}

}  // namespace

std::optional<long> evaluations_to_target(const std::vector<TracePoint>& trace, double target) {
  check_target(target);
  for (const TracePoint& p : trace)
    if (p.best <= target) return p.evaluations;
  return std::nullopt;
}

long runtime_to_target(const TrialRecord& trial, double target) {
  return evaluations_to_target(trial.trace, target).value_or(trial_cost(trial));
}

double success_rate(const std::vector<TrialRecord>& trials, double target) {
  check_trials(trials, "success rate");
  const auto hits = std::count_if(trials.begin(), trials.end(), [&](const TrialRecord& t) {
    return evaluations_to_target(t.trace, target).has_value();
  });
  return double(hits) / double(trials.size());
}

double expected_runtime(const std::vector<TrialRecord>& trials, double target) {
  check_trials(trials, "expected runtime");
  double spent = 0.0;
  long successes = 0;
  for (const TrialRecord& t : trials) {
    spent += double(runtime_to_target(t, target));
    if (evaluations_to_target(t.trace, target)) ++successes;
  }
  return successes == 0 ? kInf : spent / double(successes);
}

std::vector<EcdfStep> runtime_ecdf(const std::vector<TrialRecord>& trials,
                                   const std::vector<double>& targets) {
  check_trials(trials, "runtime ECDF");
  if (targets.empty()) throw InputError("runtime ECDF: no targets");
  std::vector<long> solved;
  for (const TrialRecord& t : trials)
    for (double target : targets)
      if (auto e = evaluations_to_target(t.trace, target)) solved.push_back(*e);
  std::sort(solved.begin(), solved.end());
  const double pairs = double(trials.size() * targets.size());
  std::vector<EcdfStep> steps;
  for (std::size_t i = 0; i < solved.size(); ++i) {
    // One step per distinct runtime, at the fraction after all its ties.
    if (i + 1 < solved.size() && solved[i + 1] == solved[i]) continue;
    steps.push_back({solved[i], double(i + 1) / pairs});
  }
  return steps;
}

std::vector<EcdfStep> runtime_ecdf(const std::vector<TrialRecord>& trials, double target) {
  return runtime_ecdf(trials, std::vector<double>{target});
}

double best_at(const std::vector<TracePoint>& trace, long evaluations) {
  // The trace holds improvements only, so the best so far is the last
  // point reached by then.
  const auto after = std::upper_bound(
      trace.begin(), trace.end(), evaluations,
      [](long e, const TracePoint& p) { return e < p.evaluations; });
  return after == trace.begin() ? kInf : std::prev(after)->best;
}

std::vector<double> fixed_budget_snapshots(const std::vector<TracePoint>& trace, long budget,
                                           const std::vector<double>& fractions) {
  if (budget < 1)
    throw InputError("fixed-budget snapshot: budget " + std::to_string(budget) +
                     " must be at least 1 evaluation");
  std::vector<double> out;
  for (double f : fractions) out.push_back(best_at(trace, evaluations_at_fraction(f, budget)));
  return out;
}

}  // namespace hystbench::stats
