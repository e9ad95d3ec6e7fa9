#pragma once
// Reads back what `hystbench run` left in a results folder: summary.json
// (experiment, problem, provenance) and every trial of trials.jsonl.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/harness/trial_result.hpp"

namespace hystbench {

struct ResultsFolder {
  std::filesystem::path dir;
  nlohmann::json summary;           // summary.json as written
  std::vector<TrialResult> trials;  // in file order
};

// InputError naming the file (and line) when a file is missing or malformed.
ResultsFolder read_results_folder(const std::filesystem::path& dir);

}  // namespace hystbench
