#pragma once
// Convergence curves: per algorithm, the median and quartiles over trials of
// the best-so-far fitness against evaluations (docs/algorithms.md#convergence-curves).
#include <filesystem>
#include <string>
#include <vector>

#include "framework/harness/trial_result.hpp"

namespace hystbench {

struct ConvergenceCurve {
  std::string label;
  std::vector<long> evaluations;  // grid, increasing
  std::vector<double> q25, median, q75;
};

// Evaluates every trial's step function (best so far is +inf before its
// first trace point) on a common grid of about `points` evaluation counts,
// log-spaced from 1 to the largest evaluation count of the trials.
ConvergenceCurve convergence_curve(const std::string& label,
                                   const std::vector<TrialResult>& trials, int points = 200);

// convergence.csv: columns label,evaluations,q25,median,q75 (long format,
// one block per algorithm), written atomically.
void write_convergence_csv(const std::filesystem::path& path,
                           const std::vector<ConvergenceCurve>& curves);

}  // namespace hystbench
