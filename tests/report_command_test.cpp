// `hystbench report`: tables recomputed from trials.jsonl, and results
// folders of one experiment run in slices merged into the report of one run.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

using hystbench::test_support::hystbench;

using hystbench::test_support::read;

using hystbench::test_support::contains;

// Two algorithms, six short trials on the sphere; the budget target makes
// the success rate and ERT columns meaningful.
std::string experiment_json(long evaluations) {
  return R"({"name": "merge_demo", "problem": {"type": "function", "name": "sphere", "dimension": 3},
  "budget": {"evaluations": )" + std::to_string(evaluations) + R"(, "target": 1e-2},
  "trials": 6, "seed": 5,
  "algorithms": [{"name": "de", "label": "DE_rand", "params": {"np": 10}},
                 {"name": "jaya", "label": "Jaya", "params": {"np": 10}}]})";
}

// One full run and two slices of the same experiment, made once for the
// suite: each run draws its figures, which takes a few seconds.
class ReportCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    dir_ = new fs::path(fs::temp_directory_path() /
                        ("hystbench_ReportCommand_" + std::to_string(stamp) + "_" +
                         std::to_string(std::random_device{}())));
    fs::create_directories(*dir_);
    std::ofstream(*dir_ / "experiment.json") << experiment_json(400);
    std::ofstream(*dir_ / "other.json") << experiment_json(500);
    run_ok("run " + path("experiment.json") + " --threads 2 --out " + path("all"));
    run_ok("run " + path("experiment.json") + " --threads 1 --trial-range 0:2 --out " + path("first"));
    run_ok("run " + path("experiment.json") + " --threads 2 --trial-range 2:6 --out " + path("rest"));
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(*dir_, ec);
    delete dir_;
  }
  static void run_ok(const std::string& args) {
    const auto r = hystbench(args);
    ASSERT_EQ(r.code, 0) << args << "\n" << r.output;
  }
  static std::string path(const std::string& name) { return (*dir_ / name).string(); }

  static fs::path* dir_;
};

fs::path* ReportCommand::dir_ = nullptr;

constexpr const char* kTables[] = {"table.md", "table.tex", "table.csv",
                                   "stats.md", "stats.tex", "stats.csv"};

TEST_F(ReportCommand, SlicesRunSeparatelyKeepTheirTrialsAndSeeds) {
  const std::string all = read(*dir_ / "all" / "trials.jsonl");
  const std::string first = read(*dir_ / "first" / "trials.jsonl");
  EXPECT_EQ(std::count(first.begin(), first.end(), '\n'), 4);  // 2 trials x 2 algorithms
  std::istringstream lines(first);
  for (std::string line; std::getline(lines, line);) {
    // wall_seconds is the only field that may differ.
    const std::string numbers = line.substr(0, line.find("\"wall_seconds\""));
    EXPECT_TRUE(contains(all, numbers)) << line;
  }
}

TEST_F(ReportCommand, MergedSlicesGiveTheTablesOfOneRun) {
  run_ok("report " + path("rest") + " " + path("first") + " --out " + path("merged"));
  for (const char* table : kTables)
    EXPECT_EQ(read(*dir_ / "merged" / table), read(*dir_ / "all" / table)) << table;
  const std::string trials = read(*dir_ / "merged" / "trials.jsonl");
  EXPECT_EQ(std::count(trials.begin(), trials.end(), '\n'), 12);
  for (const char* f : {"summary.json", "convergence.gp", "boxplot.gp", "boxplot.csv", "ecdf.gp",
                        "ecdf.csv"})
    EXPECT_TRUE(fs::exists(*dir_ / "merged" / f)) << f;
}

TEST_F(ReportCommand, RecomputesOneFolderInPlace) {
  run_ok("run " + path("experiment.json") + " --trial-range 0:2 --out " + path("again"));
  const std::string before = read(*dir_ / "again" / "stats.md");
  fs::remove(*dir_ / "again" / "stats.md");
  run_ok("report " + path("again"));
  EXPECT_EQ(read(*dir_ / "again" / "stats.md"), before);
}

TEST_F(ReportCommand, StatisticsTableHasMarksErtAndSnapshots) {
  const std::string md = read(*dir_ / "all" / "stats.md");
  for (const char* part : {"| Algorithm | Mark | p_Holm | Success | ERT | f@10 % | f@50 % | f@100 % |",
                           "ref.", "+/=/-: ", "α = 0.05", "Holm-corrected", "6 trials per algorithm",
                           "budget 400 evaluations", "Success, ERT: reaching 0.01000"})
    EXPECT_TRUE(contains(md, part)) << part << " missing from:\n" << md;
  const std::string readme = read(*dir_ / "all" / "README.md");
  EXPECT_TRUE(contains(readme, "target fitness 0.01000 (budget target)")) << readme;
  const std::string tex = read(*dir_ / "all" / "stats.tex");
  for (const char* part : {"\\toprule", "\\midrule", "\\bottomrule", "DE\\_rand",
                           "$p_{\\mathrm{Holm}}$", "$f_{10\\%}$"})
    EXPECT_TRUE(contains(tex, part)) << part << " missing from:\n" << tex;
  EXPECT_FALSE(contains(tex, "DE_rand")) << "unescaped underscore";
  EXPECT_TRUE(contains(read(*dir_ / "all" / "stats.csv"),
                       "algorithm,reference,mark,p_holm,successes,trials,success_rate,ert,"
                       "f_at_10pct,f_at_50pct,f_at_100pct\n"));
}

TEST_F(ReportCommand, ReferenceOptionPicksTheComparedAlgorithm) {
  run_ok("report " + path("first") + " " + path("rest") + " --out " + path("jaya") +
         " --reference Jaya");
  const std::string md = read(*dir_ / "jaya" / "stats.md");
  EXPECT_TRUE(contains(md, "rank-sum test against Jaya")) << md;
  EXPECT_TRUE(contains(read(*dir_ / "jaya" / "README.md"), "reference Jaya (chosen by the user)"));
  EXPECT_TRUE(contains(md, "| Jaya | ref. |")) << md;
  const auto bad = hystbench("report " + path("all") + " --reference PSO");
  EXPECT_EQ(bad.code, 2);
  EXPECT_TRUE(contains(bad.output, "--reference PSO")) << bad.output;
  EXPECT_TRUE(contains(bad.output, "DE_rand, Jaya")) << bad.output;
}

TEST_F(ReportCommand, RefusesFoldersOfDifferentExperiments) {
  run_ok("run " + path("other.json") + " --trial-range 2:6 --out " + path("other"));
  const auto r = hystbench("report " + path("first") + " " + path("other") + " --out " + path("bad"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "experiment.budget.evaluations differs between")) << r.output;
  EXPECT_FALSE(fs::exists(*dir_ / "bad" / "trials.jsonl"));
}

TEST_F(ReportCommand, RefusesTheSameTrialTwice) {
  const auto r = hystbench("report " + path("first") + " " + path("all") + " --out " + path("twice"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "appears twice")) << r.output;
}

TEST_F(ReportCommand, SeveralFoldersNeedOut) {
  const auto r = hystbench("report " + path("first") + " " + path("rest"));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(contains(r.output, "--out")) << r.output;
}

TEST_F(ReportCommand, WithoutATargetTheEcdfIsSkippedWithANote) {
  std::string text = experiment_json(400);
  text.erase(text.find(R"(, "target": 1e-2)"), std::string(R"(, "target": 1e-2)").size());
  std::ofstream(*dir_ / "no_target.json") << text;
  const auto r = hystbench("run " + path("no_target.json") + " --trial-range 0:2 --out " +
                           path("no_target"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "No runtime ECDF: no target fitness is known")) << r.output;
  EXPECT_FALSE(fs::exists(*dir_ / "no_target" / "ecdf.gp"));
  EXPECT_TRUE(fs::exists(*dir_ / "no_target" / "boxplot.gp"));
  EXPECT_TRUE(contains(read(*dir_ / "no_target" / "README.md"), "No target fitness is known"));
}

TEST_F(ReportCommand, RunRejectsABadTrialRange) {
  for (const char* range : {"3:2", "0:7", "a:b", "4"}) {
    const auto r = hystbench("run " + path("experiment.json") + " --trial-range " + range +
                             " --out " + path("never"));
    EXPECT_EQ(r.code, 2) << range;
    EXPECT_TRUE(contains(r.output, std::string("--trial-range ") + range)) << r.output;
  }
  EXPECT_FALSE(fs::exists(*dir_ / "never" / "trials.jsonl"));
}

}  // namespace
