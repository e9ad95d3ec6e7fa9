#pragma once
// Everything a finished campaign leaves in its results folder besides
// trials.jsonl: summary.json, the tables (table.*, stats.*), convergence.csv
// and the figures.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/harness/algorithm_summary.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

struct WrittenReport {
  std::vector<AlgorithmSummary> summaries;
  std::vector<std::filesystem::path> files;    // tables, summary, csv
  std::vector<std::filesystem::path> figures;  // rendered images
  std::string note;                            // e.g. how to render without gnuplot
};

// `results` is grouped per algorithm in experiment order (run_campaign's
// shape), each group in trial order. `reference` labels the algorithm the
// rank-sum marks compare against; empty: the one with the best median.
WrittenReport write_report(const std::filesystem::path& dir, const Experiment& experiment,
                           const Problem& problem,
                           const std::vector<std::vector<TrialResult>>& results, int threads,
                           const std::string& reference = "");

// "5000 evaluations", "100 iterations or 60 s", ...
std::string describe_budget(const Budget& budget);

}  // namespace hystbench
