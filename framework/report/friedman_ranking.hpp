#pragma once
// The algorithms of several results folders, one per problem or data set,
// ranked with the Friedman test (docs/algorithms.md#friedman-test): each folder is a
// block, its algorithms are ranked by the mean (or median) final fitness of
// their trials, and the average ranks are compared with the Iman-Davenport
// statistic, the Nemenyi critical difference and Holm-corrected tests
// against a control algorithm.
#include <optional>
#include <string>
#include <vector>

#include "framework/report/results_reader.hpp"
#include "framework/stats/friedman.hpp"

namespace hystbench {

enum class RankStatistic { Mean, Median };

struct FriedmanRanking {
  RankStatistic statistic = RankStatistic::Mean;
  std::vector<std::string> labels;  // algorithms, in the first folder's order
  std::vector<std::string> blocks;  // one name per folder: its folder name
  std::vector<std::string> problems;  // Problem::name() recorded by each folder
  std::vector<long> trials;           // trials per algorithm in each folder
  std::vector<std::string> budgets;   // each folder's budget, e.g. "20000 evaluations"
  std::vector<std::vector<double>> values;  // [block][algorithm] mean/median final fitness
  std::vector<std::vector<double>> ranks;   // [block][algorithm], 1 = best
  stats::FriedmanResult test;
  std::optional<double> critical_difference;  // Nemenyi, alpha 0.05; none beyond 10 algorithms
  int control = 0;                  // index into labels
  bool control_chosen = false;      // false: the best average rank
  std::vector<stats::ControlComparison> versus_control;
};

// InputError when fewer than 2 folders are given, when a folder lacks an
// algorithm of the first one (or has one more), naming the folder and the
// label, or when `control` is not a label. `control` empty: the algorithm
// with the lowest average rank.
FriedmanRanking rank_folders(const std::vector<ResultsFolder>& folders, RankStatistic statistic,
                             const std::string& control);

std::string to_string(RankStatistic s);

}  // namespace hystbench
