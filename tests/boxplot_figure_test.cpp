#include <gtest/gtest.h>

#include "tests/temp_dir.hpp"

#include <string>
#include <vector>

#include "framework/report/runtime_figures.hpp"

namespace hystbench {
namespace {

using test_support::contains;
using test_support::read;
using test_support::TempDir;

Experiment experiment(const std::vector<std::string>& labels) {
  nlohmann::json algorithms = nlohmann::json::array();
  for (const auto& l : labels) algorithms.push_back({{"name", "de"}, {"label", l}});
  return Experiment::from_json({{"name", "t"},
                                {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", 2}}},
                                {"budget", {{"evaluations", 100}}},
                                {"trials", 2},
                                {"algorithms", algorithms}},
                               "test");
}

// Two trials per algorithm, final fitness `low` and `high`.
std::vector<std::vector<TrialResult>> finals(std::size_t algorithms, double low, double high) {
  std::vector<std::vector<TrialResult>> results(algorithms);
  for (std::size_t a = 0; a < algorithms; ++a)
    for (double best : {low, high}) {
      TrialResult r;
      r.algorithm_index = static_cast<int>(a);
      r.trial = static_cast<long>(results[a].size());
      r.best = best;
      r.evaluations = 100;
      r.stop = StopReason::Evaluations;
      results[a].push_back(r);
    }
  return results;
}

std::string boxplot_script(const std::vector<std::string>& labels, double low, double high) {
  TempDir dir;
  ReportContext ctx;
  ctx.experiment = "t";
  ctx.trials = 2;
  return read(write_boxplot_figure(dir.path(), experiment(labels), finals(labels.size(), low, high), ctx));
}

TEST(BoxplotFigure, ManyLongLabelsAreTurnedSoTheyDoNotOverlap) {
  std::vector<std::string> many;
  for (int k = 0; k < 14; ++k) many.push_back("algorithm-" + std::to_string(k));
  EXPECT_TRUE(contains(boxplot_script(many, 1, 2), "noenhanced rotate by 45 right"));
  EXPECT_FALSE(contains(boxplot_script({"DE", "GA", "DETVSF", "MEDE"}, 1, 2), "rotate"));
}

TEST(BoxplotFigure, PowersOfTenOnlyWhenTheValuesSpanADecade) {
  const std::string wide = boxplot_script({"A", "B"}, 1.2e4, 3e6);
  EXPECT_TRUE(contains(wide, "set logscale y"));
  EXPECT_TRUE(contains(wide, "set format y \"10^{%L}\""));
  const std::string narrow = boxplot_script({"A", "B"}, 1.2e4, 1.3e4);
  EXPECT_TRUE(contains(narrow, "set logscale y"));
  EXPECT_FALSE(contains(narrow, "set format y"));
}

// Final fitness 1 and 2 per algorithm, reached at evaluation 100.
std::string ecdf_script(double target) {
  TempDir dir;
  ReportContext ctx;
  ctx.experiment = "t";
  ctx.trials = 2;
  auto results = finals(2, 1.0, 2.0);
  for (auto& trials : results)
    for (auto& r : trials) r.trace = {{10, 5.0}, {100, r.best}};
  return read(*write_ecdf_figure(dir.path(), experiment({"A", "B"}), results, target, ctx));
}

TEST(EcdfFigure, SaysInThePlotWhenNoTrialReachedTheTarget) {
  const std::string none = ecdf_script(0.5);
  EXPECT_TRUE(contains(none, "\n# no trial reached the target f ≤ 0.5: every line stays at 0.\n"))
      << none;
  EXPECT_TRUE(contains(none, "\nset label 1 \"no trial reached the target f ≤ 0.5\" at graph 0.5, "
                             "graph 0.5 center front"))
      << none;
  EXPECT_FALSE(contains(ecdf_script(1.5), "no trial reached"));
}

}  // namespace
}  // namespace hystbench
