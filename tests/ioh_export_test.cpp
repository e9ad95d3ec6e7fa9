// `hystbench export ioh` read back: every run of the IOHprofiler files is a
// trial of trials.jsonl, with the same final best, the same evaluation count
// and rows that only improve.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "framework/export/ioh_export.hpp"
#include "framework/harness/trial_log.hpp"
#include "run_command.hpp"
#include "source_tree.hpp"
#include "temp_dir.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;
using test_support::contains;
using test_support::hystbench;
using test_support::kSourceRoot;
using test_support::TempDir;

const fs::path kTable1 = kSourceRoot / "results/paper/mede_table1";

using Rows = std::vector<std::pair<long, double>>;

// The runs of a .dat file, split at their header lines.
std::vector<Rows> read_dat(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Rows> runs;
  std::string line;
  while (std::getline(in, line)) {
    if (line == "evaluations raw_y") {
      runs.emplace_back();
      continue;
    }
    std::istringstream row(line);
    long evals = 0;
    double y = 0;
    row >> evals >> y;
    EXPECT_TRUE(row && !runs.empty()) << file << ": " << line;
    if (!runs.empty()) runs.back().emplace_back(evals, y);
  }
  return runs;
}

std::map<std::string, std::vector<TrialResult>> trials_by_label(const fs::path& dir) {
  std::map<std::string, std::vector<TrialResult>> by_label;
  for (auto& t : read_trial_log(dir / "trials.jsonl").trials) by_label[t.label].push_back(t);
  for (auto& [label, trials] : by_label)
    std::sort(trials.begin(), trials.end(),
              [](const auto& a, const auto& b) { return a.trial < b.trial; });
  return by_label;
}

void expect_rows_of(const Rows& rows, const TrialResult& t) {
  ASSERT_FALSE(rows.empty());
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i].first, rows[i - 1].first) << t.label << " trial " << t.trial;
    const bool last = i + 1 == rows.size();
    if (last) EXPECT_LE(rows[i].second, rows[i - 1].second);
    else EXPECT_LT(rows[i].second, rows[i - 1].second) << t.label << " trial " << t.trial;
  }
  EXPECT_EQ(rows.back().first, t.evaluations);
  EXPECT_EQ(rows.back().second, t.best);  // bit for bit: written in shortest round-trip form
}

TEST(IohExport, MedeTable1ReadsBackAsItsTrials) {
  TempDir tmp;
  const fs::path out = tmp.path() / "ioh";
  const auto r = hystbench("export ioh " + kTable1.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "Exported 120 runs of 4 algorithms")) << r.output;
  const auto by_label = trials_by_label(kTable1);
  ASSERT_EQ(by_label.size(), 4u);
  for (const auto& [label, trials] : by_label) {
    const fs::path json_file = out / label / "IOHprofiler_f1_hammerstein_default.csv.json";
    ASSERT_TRUE(fs::exists(json_file)) << json_file;
    const auto meta = nlohmann::json::parse(std::ifstream(json_file));
    EXPECT_EQ(meta["function_id"], 1);
    EXPECT_EQ(meta["maximization"], false);
    EXPECT_EQ(meta["algorithm"]["name"], label);
    EXPECT_TRUE(contains(meta["algorithm"]["info"].get<std::string>(), " np=")) << label;
    const auto& scenario = meta["scenarios"][0];
    EXPECT_EQ(scenario["dimension"], 13);
    const auto runs = scenario["runs"];
    const auto dat = read_dat(out / label / scenario["path"].get<std::string>());
    ASSERT_EQ(runs.size(), trials.size());
    ASSERT_EQ(dat.size(), trials.size());
    for (std::size_t i = 0; i < trials.size(); ++i) {
      EXPECT_EQ(runs[i]["evals"], trials[i].evaluations);
      EXPECT_EQ(runs[i]["best"]["y"].get<double>(), trials[i].best);
      EXPECT_EQ(runs[i]["best"]["x"].get<std::vector<double>>(), trials[i].best_x);
      EXPECT_LE(runs[i]["best"]["evals"].get<long>(), trials[i].evaluations);
      expect_rows_of(dat[i], trials[i]);
    }
  }
}

TEST(IohExport, RowsKeepOnlyImprovementsAndEndAtTheLastEvaluation) {
  TrialResult t;
  t.best = 2.0;
  t.evaluations = 50;
  t.trace = {{1, 9.0}, {4, 9.0}, {7, 5.0}, {20, 2.0}};
  EXPECT_EQ(ioh_rows(t), (Rows{{1, 9.0}, {7, 5.0}, {20, 2.0}, {50, 2.0}}));
  t.evaluations = 20;
  EXPECT_EQ(ioh_rows(t), (Rows{{1, 9.0}, {7, 5.0}, {20, 2.0}}));
}

TEST(IohExport, FailedTrialsAreLeftOutWithANote) {
  ResultsFolder folder = read_results_folder(kTable1);
  folder.trials[0].stop = StopReason::Failed;
  folder.trials[0].message = "the model diverged";
  const IohExport exported = export_ioh({folder});
  EXPECT_EQ(exported.runs, 119);
  ASSERT_EQ(exported.skipped.size(), 1u);
  EXPECT_TRUE(contains(exported.skipped[0], "failed (the model diverged)")) << exported.skipped[0];
}

TEST(IohExport, NamesBecomeFileNameParts) {
  EXPECT_EQ(ioh_safe_name("hammerstein(default.csv)"), "hammerstein_default.csv");
  EXPECT_EQ(ioh_safe_name("control(avc_beam, vss_fxlms)"), "control_avc_beam_vss_fxlms");
  EXPECT_EQ(ioh_safe_name("DE@mede table1"), "DE_mede_table1");
  EXPECT_EQ(ioh_safe_name("(())"), "unnamed");
}

TEST(IohExport, SameLabelInTwoExperimentsIsTold) {
  TempDir tmp;
  const fs::path out = tmp.path() / "ioh";
  const auto fair = kSourceRoot / "results/paper/mede_table1_fair";
  const auto r = hystbench("export ioh " + kTable1.string() + " " + fair.string() + " --out " +
                           out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "DE" / "IOHprofiler_f1_hammerstein_default.csv.json"));
  const auto renamed = out / "DE_mede_table1_fair" / "IOHprofiler_f1_hammerstein_default.csv.json";
  ASSERT_TRUE(fs::exists(renamed)) << r.output;
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(renamed))["algorithm"]["name"],
            "DE@mede_table1_fair");
}

TEST(IohExport, RefusesToOverwriteAndNonResultsFolders) {
  TempDir tmp;
  const fs::path out = tmp.path() / "ioh";
  ASSERT_EQ(hystbench("export ioh " + kTable1.string() + " --out " + out.string()).code, 0);
  const auto again = hystbench("export ioh " + kTable1.string() + " --out " + out.string());
  EXPECT_EQ(again.code, 2);
  EXPECT_TRUE(contains(again.output, "already holds an IOHprofiler export")) << again.output;
  // --force replaces the whole earlier export: no run of another folder stays.
  const auto fair = kSourceRoot / "results/paper/mede_table1_fair";
  ASSERT_EQ(hystbench("export ioh " + fair.string() + " --out " + out.string()).code, 2);
  ASSERT_EQ(hystbench("export ioh " + fair.string() + " --out " + out.string() + " --force").code, 0);
  const auto meta = nlohmann::json::parse(
      test_support::read(out / "DE" / "IOHprofiler_f1_hammerstein_default.csv.json"));
  EXPECT_EQ(meta["scenarios"][0]["runs"][0]["best"]["y"].get<double>(),
            trials_by_label(fair).at("DE").front().best);
  const auto not_results = hystbench("export ioh " + tmp.path().string() + " --out " +
                                     (tmp.path() / "x").string());
  EXPECT_EQ(not_results.code, 2);
  EXPECT_TRUE(contains(not_results.output, "summary.json")) << not_results.output;
  EXPECT_FALSE(fs::exists(tmp.path() / "x"));
}

}  // namespace
}  // namespace hystbench
