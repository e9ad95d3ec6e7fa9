#pragma once
// Statistics of one algorithm's trials: one entry of summary.json and one
// row of the tables.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/harness/trial_result.hpp"

namespace hystbench {

struct AlgorithmSummary {
  std::string label;
  std::string name;             // plugin name
  nlohmann::json params;        // validated parameters, defaults filled in
  long trials = 0;              // finished trials
  long failed = 0;              // trials whose optimizer threw or found nothing finite
  std::string first_failure;    // message of the first failed trial (trial order)
  // Statistics of the final best fitness over the successful trials:
  double best = 0.0;            // = min
  double mean = 0.0;
  double worst = 0.0;           // = max
  double median = 0.0;
  double std = 0.0;             // sample standard deviation (divides by R - 1)
  double min = 0.0;
  double max = 0.0;
  double mean_evaluations = 0.0;
  double mean_iterations = 0.0;
  double wall_seconds = 0.0;    // summed over trials
  std::vector<std::string> parameter_names;
  std::vector<double> best_x;   // parameters of the best trial
  long best_trial = -1;         // index of the best trial

  nlohmann::json to_json() const;
};

// `results` are the trials of one algorithm, in any order.
AlgorithmSummary summarize(const std::string& label, const std::string& name,
                           const nlohmann::json& params,
                           const std::vector<std::string>& parameter_names,
                           std::vector<TrialResult> results);

}  // namespace hystbench
