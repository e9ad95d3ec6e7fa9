#pragma once
// The comparison statistics of a campaign (docs/algorithms.md#rank-sum-test,
// docs/algorithms.md#runtime-measures), one row per algorithm: the rank-sum
// mark against a reference algorithm with Holm-adjusted p-values, success
// rate and ERT to a target, and the median best-so-far value at fixed
// fractions of the evaluation budget.
#include <optional>
#include <string>
#include <vector>

#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

// Fractions of the evaluation budget at which best-so-far values are shown.
inline const std::vector<double> kSnapshotFractions{0.1, 0.5, 1.0};

struct AlgorithmStatistics {
  std::string label;
  bool reference = false;
  char mark = '=';             // '+', '=' or '-' from the reference's view; ' ' for it
  double p_holm = 1.0;         // NaN for the reference or without a test
  bool p_exact = false;        // the raw p came from the exact rank-sum distribution
  long trials = 0;             // all trials, failed ones included
  long successes = 0;          // trials that reached the target
  double success_rate = 0.0;   // NaN without a target
  double ert = 0.0;            // evaluations; +inf without success, NaN without a target
  std::vector<double> snapshot_medians;  // per kSnapshotFractions; NaN without a budget
};

struct CampaignStatistics {
  std::string reference;           // label of the reference algorithm
  bool reference_chosen = false;   // false: picked as the best median
  double alpha = 0.05;
  std::optional<double> target;    // fitness target of the runtime measures
  std::string target_origin;       // "budget target" or "1.01 × noise floor"
  // Evaluations the snapshot fractions refer to: the evaluation budget, or
  // without one (an iteration or time budget) the most evaluations any trial
  // used, so that the columns still compare the algorithms at equal cost.
  std::optional<long> budget;
  bool budget_from_trials = false;
  std::vector<AlgorithmStatistics> rows;
};

// The target: the budget's target fitness when set, else 1.01 x the noise
// floor when known (a fit within 1 % of the best the data allow).
std::optional<double> runtime_target(const Experiment& e, std::optional<double> noise_floor);

// InputError naming --reference unless `reference` is empty or a label of
// the experiment; called before any work so that a typo costs nothing.
void check_reference(const Experiment& e, const std::string& reference);

// `results` grouped per algorithm in experiment order. `reference` is a
// label, or empty for the algorithm with the lowest median final fitness
// (the first such one on ties). InputError for an unknown label.
CampaignStatistics campaign_statistics(const Experiment& e,
                                       const std::vector<std::vector<TrialResult>>& results,
                                       const std::string& reference,
                                       std::optional<double> noise_floor);

}  // namespace hystbench
