#pragma once
// Merges results folders of one experiment run in pieces (separate runs or
// machines, disjoint trials) into the shape write_report takes. Folders
// must agree on the experiment, the problem and the build that ran them
// (version and commit; host, date and threads may differ).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/harness/experiment.hpp"
#include "framework/report/results_reader.hpp"

namespace hystbench {

struct MergedResults {
  Experiment experiment;  // base_dir: the first folder's experiment_dir
  std::vector<std::vector<TrialResult>> results;  // per algorithm, in trial order
};

// InputError naming the field that differs ("experiment.budget.evaluations
// differs between A and B"), or the (algorithm, trial) pair found twice.
MergedResults merge_results(const std::vector<ResultsFolder>& folders);

// Path of the first place where `a` and `b` differ ("budget.evaluations",
// "algorithms[1].params.np"); empty when they are equal.
std::string first_difference(const nlohmann::json& a, const nlohmann::json& b,
                             const std::string& path = "");

}  // namespace hystbench
