// `hystbench svr` end to end on a short generated record: the per-signal
// table, svr.json's rows and their relative error, the saved model giving
// the same errors when loaded, and the same numbers on 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "framework/io/json_file.hpp"
#include "framework/io/measurement.hpp"
#include "framework/svr/svr_model.hpp"
#include "framework/svr/svr_run.hpp"
#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

struct Piece {
  std::string label;
  double f0, f1, seconds;  // a sine (f0 == f1) or a linear chirp
};

// A rate-dependent loop: a play operator, then a first-order lag, at 1 kHz.
Measurement record(const std::vector<Piece>& pieces) {
  std::vector<double> u, y;
  std::vector<std::string> labels;
  double play = 0.0, lag = 0.0;
  for (const Piece& p : pieces) {
    const int n = int(std::lround(p.seconds * 1000));
    for (int k = 0; k < n; ++k) {
      const double t = k / 1000.0;
      const double phase = 2 * M_PI * (p.f0 * t + (p.f1 - p.f0) * t * t / (2 * p.seconds));
      u.push_back(75.0 - 75.0 * std::cos(phase));
      play = std::clamp(play, u.back() - 10.0, u.back() + 10.0);
      lag = 0.8 * lag + 0.2 * 0.1 * play;
      y.push_back(lag);
      labels.push_back(p.label);
    }
  }
  Measurement m;
  m.u = Eigen::Map<Eigen::VectorXd>(u.data(), Eigen::Index(u.size()));
  m.y = Eigen::Map<Eigen::VectorXd>(y.data(), Eigen::Index(y.size()));
  m.t = Eigen::VectorXd::LinSpaced(m.u.size(), 0.0, double(m.u.size() - 1) / 1000.0);
  m.segment = labels;
  return m;
}

nlohmann::json experiment() {
  return {{"name", "svr_short"},
          {"stage1", {{"data", "train.csv"}, {"segment", "train"}}},
          {"stage2", {{"data", "train.csv"}, {"segment", "scan"}}},
          {"tests", {{{"data", "test.csv"}}}},
          {"units", {{"u", "V"}, {"y", "um"}}},
          {"lags", {{"m", 2}, {"n", 2}}},
          {"search",
           {{"optimizer", {{"name", "pso"}, {"params", {{"swarm", 6}}}}},
            {"evaluations", 12},
            {"problem", {{"log10_C", {-1, 2}}, {"log10_epsilon", {-3, -1}}, {"log10_sigma", {-1, 1}}}}}},
          {"arx", {{"p_max", 2}, {"q_max", 2}}},
          {"discard", 0.2},
          {"seed", 5}};
}

TEST(SvrCommand, PerSignalTableOnAShortGeneratedRecord) {
  test_support::TempDir dir;
  write_measurement(dir.path() / "train.csv", record({{"train", 2, 2, 1.5}, {"scan", 1, 40, 2}}));
  const Measurement test = record({{"5 Hz", 5, 5, 1}, {"20 Hz", 20, 20, 0.5}});
  write_measurement(dir.path() / "test.csv", test);
  std::ofstream(dir.path() / "svr.json") << experiment().dump();

  std::vector<nlohmann::json> results;
  for (const char* threads : {"1", "2"}) {
    const fs::path out = dir.path() / (std::string("out") + threads);
    const auto r = test_support::hystbench("svr " + (dir.path() / "svr.json").string() + " --out " +
                                           out.string() + " --threads " + threads);
    ASSERT_EQ(r.code, 0) << r.output;
    results.push_back(read_json_file(out / "svr.json", "svr.json"));
  }
  const nlohmann::json& j = results[0];
  for (const char* key : {"hyperparameters", "orders", "rows"}) EXPECT_EQ(j[key], results[1][key]) << key;

  const auto& h = j["hyperparameters"];
  EXPECT_DOUBLE_EQ(h["gamma"].get<double>(), 1.0 / (2.0 * std::pow(h["sigma"].get<double>(), 2)));
  EXPECT_EQ(j["orders"]["m"], 2);
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_EQ(j["rows"][0]["signal"], "5 Hz");
  EXPECT_EQ(j["rows"][1]["signal"], "20 Hz");

  // RE from the row's RMSE and the measured output over the scored samples;
  // the loaded model reproduces the RMSE exactly.
  const SvrHammerstein model = SvrHammerstein::from_json(
      read_json_file(dir.path() / "out1" / "svr_model.json", "model"), "svr_model.json");
  Eigen::Index begin = 0;
  for (const auto& row : j["rows"]) {
    const Eigen::Index n = row["samples"].get<Eigen::Index>(), scored = row["scored_samples"].get<Eigen::Index>();
    const Eigen::VectorXd u = test.u.segment(begin, n), y = test.y.segment(begin, n);
    const SignalScore s = score(y, model.simulate(u, y), model.one_step(u, y), n - scored);
    EXPECT_EQ(row["svr"]["rmse"].get<double>(), s.rmse);
    EXPECT_EQ(row["svr"]["rmse_one_step"].get<double>(), s.rmse_one_step);
    const double re = s.rmse * std::sqrt(double(scored) / y.tail(scored).squaredNorm());
    EXPECT_NEAR(row["svr"]["re"].get<double>(), re, 1e-12 * re);
    EXPECT_LT(row["svr"]["re"].get<double>(), 0.5) << row;
    EXPECT_TRUE(row["greybox"].is_null());
    begin += n;
  }
  const std::string table = test_support::read(dir.path() / "out1" / "table.md");
  EXPECT_TRUE(test_support::contains(table, "| 5 Hz |")) << table;
  EXPECT_TRUE(test_support::contains(table, "| 20 Hz |")) << table;
  EXPECT_TRUE(test_support::contains(table, "SVR ARMSE (um)")) << table;
  for (const char* file : {"aic.csv", "table.tex", "table.csv", "loop_5-Hz.gp", "loop_20-Hz.csv", "relative_error.gp"})
    EXPECT_TRUE(fs::exists(dir.path() / "out1" / file)) << file;

  // The model file does not name its training record, so compare cannot
  // call the numbers estimation or test numbers, and says so.
  const auto c = test_support::hystbench("compare --data " + (dir.path() / "test.csv").string() + " --fit " +
                                         (dir.path() / "out1" / "svr_model.json").string() + " --out " +
                                         (dir.path() / "compare").string());
  ASSERT_EQ(c.code, 0) << c.output;
  const std::string report = test_support::read(dir.path() / "compare" / "report.md");
  EXPECT_TRUE(test_support::contains(report, "| not held out | ")) << report;
  EXPECT_TRUE(test_support::contains(report, "the model file does not name the record it was fitted on")) << report;
}

}  // namespace
}  // namespace hystbench
