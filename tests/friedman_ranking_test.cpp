// Friedman ranking of results folders (one per data set): block values,
// ranks, the test against hand-computed numbers, the tables, and the
// `hystbench rank` and `run --data` commands as a user runs them.
#include "framework/report/friedman_ranking.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/report/ranking_tables.hpp"
#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;
using test_support::contains;
using test_support::read;

constexpr double kInf = std::numeric_limits<double>::infinity();

// A results folder as read back from disk: labels in the summary, one
// trial per value (+inf: a failed trial).
ResultsFolder folder(const std::string& name,
                     const std::vector<std::pair<std::string, std::vector<double>>>& finals) {
  ResultsFolder f;
  f.dir = fs::path("runs") / name;
  nlohmann::json algorithms = nlohmann::json::array();
  for (const auto& [label, values] : finals) {
    algorithms.push_back({{"name", "de"}, {"label", label}});
    long trial = 0;
    for (double v : values) {
      TrialResult t;
      t.label = label;
      t.trial = trial++;
      t.best = v;
      t.stop = std::isinf(v) ? StopReason::Failed : StopReason::Evaluations;
      f.trials.push_back(t);
    }
  }
  f.summary = {{"experiment", {{"algorithms", algorithms}, {"budget", {{"evaluations", 100}}}}},
               {"problem", {{"name", "function(" + name + ")"}}}};
  return f;
}

// Three data sets, hand-ranked by the mean final fitness:
//   d1: A 2, B 2, C 6       ranks 1.5 1.5 3
//   d2: A 1, B 4, C 2       ranks 1   3   2
//   d3: A inf (one failed trial), B 1, C 3   ranks 3 1 2
// Average ranks 11/6, 11/6, 7/3; chi2_F = 12*3/(3*4) (2 (11/6)^2 + (7/3)^2 - 12) = 0.5.
std::vector<ResultsFolder> three_data_sets() {
  return {folder("d1", {{"A", {1, 3}}, {"B", {2, 2}}, {"C", {5, 7}}}),
          folder("d2", {{"A", {1, 1}}, {"B", {4, 4}}, {"C", {2, 2}}}),
          folder("d3", {{"A", {kInf, 1}}, {"B", {1, 1}}, {"C", {3, 3}}})};
}

TEST(FriedmanRanking, RanksEachFolderByTheMeanWithFailedTrialsLast) {
  const auto r = rank_folders(three_data_sets(), RankStatistic::Mean, "");
  EXPECT_EQ(r.blocks, (std::vector<std::string>{"d1", "d2", "d3"}));
  EXPECT_EQ(r.ranks[0], (std::vector<double>{1.5, 1.5, 3}));
  EXPECT_EQ(r.ranks[1], (std::vector<double>{1, 3, 2}));
  EXPECT_EQ(r.ranks[2], (std::vector<double>{3, 1, 2}));
  EXPECT_DOUBLE_EQ(r.test.average_ranks[0], 11.0 / 6);
  EXPECT_DOUBLE_EQ(r.test.average_ranks[2], 7.0 / 3);
  EXPECT_NEAR(r.test.chi2, 0.5, 1e-12);
  EXPECT_EQ(r.control, 0);  // A and B tie for the best average rank: the first
  EXPECT_FALSE(r.control_chosen);
  ASSERT_EQ(r.versus_control.size(), 2u);
  EXPECT_EQ(r.trials, (std::vector<long>{2, 2, 2}));
  ASSERT_TRUE(r.critical_difference);
  // Nemenyi: q_0.05(3) = 2.343, CD = 2.343 sqrt(3*4 / (6*3)).
  EXPECT_NEAR(*r.critical_difference, 2.343 * std::sqrt(12.0 / 18), 1e-12);
}

// trials.jsonl lists trials in finishing order, which varies with the
// thread count; the mean is taken in trial order, so the order of the file
// cannot move its last bits (1e16 + 1 + 1 != 1 + 1 + 1e16 in doubles).
TEST(FriedmanRanking, MeanDoesNotDependOnTheOrderOfTrialsInTheFile) {
  auto sets = std::vector<ResultsFolder>{folder("d1", {{"A", {1e16, 1, 1}}, {"B", {3, 3, 3}}}),
                                         folder("d2", {{"A", {1, 1, 1}}, {"B", {2, 2, 2}}})};
  const double in_order = rank_folders(sets, RankStatistic::Mean, "").values[0][0];
  std::reverse(sets[0].trials.begin(), sets[0].trials.end());
  EXPECT_EQ(rank_folders(sets, RankStatistic::Mean, "").values[0][0], in_order);
}

TEST(FriedmanRanking, MedianRankingIgnoresAnOutlierThatMovesTheMean) {
  const std::vector<ResultsFolder> sets{folder("d1", {{"A", {1, 1, 100}}, {"B", {2, 2, 2}}}),
                                        folder("d2", {{"A", {1, 1, 1}}, {"B", {2, 2, 2}}})};
  EXPECT_EQ(rank_folders(sets, RankStatistic::Mean, "").ranks[0], (std::vector<double>{2, 1}));
  EXPECT_EQ(rank_folders(sets, RankStatistic::Median, "").ranks[0], (std::vector<double>{1, 2}));
}

TEST(FriedmanRanking, ChosenControlIsTestedAgainstTheOthers) {
  const auto r = rank_folders(three_data_sets(), RankStatistic::Mean, "C");
  EXPECT_EQ(r.control, 2);
  EXPECT_TRUE(r.control_chosen);
  for (const auto& c : r.versus_control) EXPECT_NE(c.algorithm, 2);
}

TEST(FriedmanRanking, RefusesFoldersWithDifferentAlgorithmsNamingFolderAndLabel) {
  auto sets = three_data_sets();
  sets[1] = folder("d2", {{"A", {1}}, {"B", {4}}, {"D", {2}}});
  try {
    rank_folders(sets, RankStatistic::Mean, "");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "d2")) << e.what();
    EXPECT_TRUE(contains(e.what(), "\"C\"")) << e.what();
  }
}

TEST(FriedmanRanking, RefusesOneFolderAndAnUnknownControl) {
  auto sets = three_data_sets();
  EXPECT_THROW(rank_folders({sets[0]}, RankStatistic::Mean, ""), InputError);
  try {
    rank_folders(sets, RankStatistic::Mean, "Z");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "--control Z")) << e.what();
    EXPECT_TRUE(contains(e.what(), "A, B, C")) << e.what();
  }
}

TEST(RankingTables, MarkdownShowsRanksBoldBestAndTheTestInTheCaption) {
  const auto md = ranking_markdown(rank_folders(three_data_sets(), RankStatistic::Mean, ""));
  EXPECT_TRUE(contains(md, "| Algorithm | d1 | d2 | d3 | Avg. rank | Mark | p_Holm |")) << md;
  EXPECT_TRUE(contains(md, "| A | 1.5 | 1 | 3 | **1.833** | ctrl. |")) << md;
  EXPECT_TRUE(contains(md, "| C | 3 | 2 | 2 | 2.333 | = |")) << md;
  EXPECT_TRUE(contains(md, "p = 0.8403 (Iman–Davenport)")) << md;
  const std::string method = ranking_method(rank_folders(three_data_sets(), RankStatistic::Mean, ""));
  EXPECT_TRUE(contains(method, "χ²_F = 0.5")) << method;
  EXPECT_TRUE(contains(method, "mean final fitness of their 2 trials")) << method;
  EXPECT_TRUE(contains(md, "`d3`: `function(d3)`, 100 evaluations")) << md;
}

TEST(RankingTables, LatexIsABooktabsTableWithAGroupedHeader) {
  const auto tex = ranking_latex(rank_folders(three_data_sets(), RankStatistic::Mean, ""));
  for (const char* part : {"\\toprule", "\\cmidrule(lr){2-4}", "\\midrule", "\\bottomrule",
                           "\\textbf{1.833}", "(Iman–Davenport)", "\\label{tab:friedman-ranks}"})
    EXPECT_TRUE(contains(tex, part)) << part << "\n" << tex;
}

// Two problems of the function family stand in for two data sets.
std::string experiment(const std::string& function) {
  return R"({"name": "rank_demo", "problem": {"type": "function", "name": ")" + function +
         R"(", "dimension": 2}, "budget": {"evaluations": 300}, "trials": 3, "seed": 9,
  "algorithms": [{"name": "de", "label": "DE", "params": {"np": 10}},
                 {"name": "jaya", "label": "Jaya", "params": {"np": 10}}]})";
}

TEST(RankCommand, RanksResultsFoldersAndRefusesAMismatchWithoutOutput) {
  test_support::TempDir tmp;
  for (const char* f : {"sphere", "rastrigin"}) {
    std::ofstream(tmp.path() / (std::string(f) + ".json")) << experiment(f);
    const auto run = test_support::hystbench("run " + (tmp.path() / f).string() + ".json --out " +
                                             (tmp.path() / f).string() + " --threads 1");
    ASSERT_EQ(run.code, 0) << run.output;
  }
  const std::string folders = (tmp.path() / "sphere").string() + " " + (tmp.path() / "rastrigin").string();
  const auto ok = test_support::hystbench("rank " + folders + " --out " + (tmp.path() / "ranks").string());
  ASSERT_EQ(ok.code, 0) << ok.output;
  EXPECT_TRUE(contains(ok.output, "Friedman average ranks (1 = best) of 2 algorithms over 2 data sets"))
      << ok.output;
  for (const char* f : {"ranks.md", "ranks.tex", "ranks.csv", "ranks.json", "ranks.gp"})
    EXPECT_TRUE(fs::exists(tmp.path() / "ranks" / f)) << f;

  std::ofstream(tmp.path() / "other.json")
      << std::string(experiment("sphere")).replace(experiment("sphere").find("Jaya"), 4, "PSO");
  ASSERT_EQ(test_support::hystbench("run " + (tmp.path() / "other.json").string() + " --out " +
                                    (tmp.path() / "other").string() + " --threads 1")
                .code,
            0);
  const auto bad = test_support::hystbench("rank " + folders + " " + (tmp.path() / "other").string() +
                                           " --out " + (tmp.path() / "bad").string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(contains(bad.output, "has no algorithm \"Jaya\"")) << bad.output;
  EXPECT_FALSE(fs::exists(tmp.path() / "bad"));
}

TEST(RunCommand, DataOptionRefusesAProblemWithoutDataFile) {
  test_support::TempDir tmp;
  std::ofstream(tmp.path() / "e.json") << experiment("sphere");
  std::ofstream(tmp.path() / "d.csv") << "t,u,y\n0,0,0\n";
  const auto r = test_support::hystbench("run " + (tmp.path() / "e.json").string() + " --data " +
                                         (tmp.path() / "d.csv").string() + " --out " +
                                         (tmp.path() / "out").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.output, "--data: the experiment's problem (function) reads no data file"))
      << r.output;
  EXPECT_FALSE(fs::exists(tmp.path() / "out"));
}

// The data file given on the command line is stored relative to the
// experiment file's folder, so summary.json names no folder of the machine.
TEST(RunCommand, DataOptionRunsTheExperimentOnAnotherDataFile) {
  test_support::TempDir tmp;
  const std::string params = (fs::path(HYSTBENCH_SOURCE_DIR) / "problems/hammerstein/data/default.params.json").string();
  tmp.write("excitation.json", R"({"sample_rate": 1000, "segments": [{"type": "sine",
    "frequency": 5, "amplitude": 500, "offset": 250, "duration": 0.4}]})");
  const auto sim = test_support::hystbench("simulate --params " + params + " --excitation " +
                                           (tmp.path() / "excitation.json").string() +
                                           " --noise 0.01 --out " + (tmp.path() / "short.csv").string());
  ASSERT_EQ(sim.code, 0) << sim.output;
  tmp.write("e.json", R"({"name": "data_demo", "problem": {"type": "hammerstein", "data": "absent.csv"},
    "budget": {"evaluations": 60}, "trials": 1, "seed": 3,
    "algorithms": [{"name": "de", "label": "DE", "params": {"np": 20}}]})");
  const auto r = test_support::hystbench("run " + (tmp.path() / "e.json").string() + " --data " +
                                         (tmp.path() / "short.csv").string() + " --out " +
                                         (tmp.path() / "out").string() + " --threads 1");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto summary = nlohmann::json::parse(read(tmp.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["experiment"]["problem"]["data"], "short.csv");
  EXPECT_EQ(summary["problem"]["name"], "hammerstein(short.csv)");
}

}  // namespace
}  // namespace hystbench
