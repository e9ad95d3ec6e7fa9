// `hystbench track` as a user runs it: Table 2 on a short run of a
// simulated actuator, the same numbers on one and two threads, a reference
// out of the actuator's range reported in its row, and an impossible design
// refused before anything is written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;
using test_support::contains;

// The actuator of the SVR work and a model of it with every parameter a
// few per cent off, references of 0.6 µm about 1.5 µm (and one of 3 µm, out
// of range), scored on one short window.
nlohmann::json experiment() {
  const nlohmann::json truth = {{"gain", 0.1},           {"hysteresis.A", 0.05}, {"hysteresis.beta", 0.01},
                                {"hysteresis.gamma", 0.002}, {"asymmetry.d2", 0.0002}, {"msd.period", 0.0025},
                                {"msd.zeta", 0.3}};
  nlohmann::json model = truth;
  for (auto& [name, value] : model.items()) value = value.get<double>() * 1.03;
  return {{"name", "short"},
          {"plant", {{"model", "hysteresis,asymmetry,msd"}, {"parameters", truth}}},
          {"sensor", {{"noise_sd", 0.01}, {"resolution", 0.01}}},
          {"amplifier", {{"min", 0}, {"max", 30}}},
          {"identified", {{"model", "hysteresis,asymmetry,msd"}, {"parameters", model}}},
          {"nominal", {{"p", 2}, {"q", 1}}},
          {"uncertainty", {{"weight", "seed"}}},
          {"controllers",
           {{{"label", "FF"}, {"type", "inverse_only"}},
            {{"label", "Hinf"}, {"type", "hinf_2dof"}, {"order", "reduced"}},
            {{"label", "PI"}, {"type", "pi"}, {"kp", 0.3}, {"ki", 300}}}},
          {"references",
           {{"amplitude", 0.6},
            {"offset", 1.5},
            {"signals", {20, 50, {10, 20, 40}, {{"hz", 20}, {"amplitude", 3.0}, {"offset", 3.0}}}}}},
          {"window", {{"settle_s", 0.1}, {"length_s", 0.05}}},
          {"seed", 3}};
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(test_support::read(p)); }

TEST(TrackCommand, Table2OnAShortRunWithEveryController) {
  test_support::TempDir temp;
  const auto file = temp.write("short.json", experiment().dump());
  const auto o = test_support::hystbench("track " + file.string() + " --out " + (temp.path() / "out").string());
  ASSERT_EQ(o.code, 0) << o.output;
  for (const char* name : {"controller.json", "tracking.json", "table.md", "table.tex", "table.csv", "bode.gp",
                           "tracking_20-Hz.gp", "tracking_10-20-40-Hz.csv"})
    EXPECT_TRUE(fs::exists(temp.path() / "out" / name)) << name;
  const nlohmann::json t = read_json(temp.path() / "out" / "tracking.json");
  ASSERT_EQ(t["rows"].size(), 12u);
  std::map<std::string, double> re;
  for (const auto& row : t["rows"]) {
    if (row["signal"] == "20 Hz amplitude 3 offset 3") {
      EXPECT_TRUE(contains(row["status"].get<std::string>(), "out of range")) << row.dump();
      continue;
    }
    EXPECT_EQ(row["status"], "") << row.dump();
    ASSERT_TRUE(row["re"].is_number()) << row.dump();
    re[row["signal"].get<std::string>() + "/" + row["controller"].get<std::string>()] = row["re"].get<double>();
    EXPECT_LT(row["inverse"]["rms_residual"].get<double>(), 1e-5);
  }
  // Feedback beats feedforward alone on a model a few per cent off, and the
  // H∞ loop tracks to a few per cent.
  for (const char* signal : {"20 Hz", "50 Hz", "10/20/40 Hz"}) {
    EXPECT_LT(re[std::string(signal) + "/Hinf"], re[std::string(signal) + "/FF"]) << signal;
    EXPECT_LT(re[std::string(signal) + "/Hinf"], 0.1) << signal;
  }
  const nlohmann::json c = read_json(temp.path() / "out" / "controller.json");
  EXPECT_LT(c["gamma_min"].get<double>(), 1.0);
  EXPECT_EQ(c["reduced"]["order"], 3);
  EXPECT_TRUE(c["full"]["stable_at_uncertainty_edges"].get<bool>());
  EXPECT_GT(c["seed_printed_design"]["K3_discrete_loop_spectral_radius"].get<double>(), 1.0);
  const std::string table = test_support::read(temp.path() / "out" / "table.md");
  EXPECT_TRUE(contains(table, "| 0.6 | 10/20/40 |")) << table;
  EXPECT_TRUE(contains(table, "†")) << table;
}

TEST(TrackCommand, SameNumbersOnOneAndTwoThreads) {
  test_support::TempDir temp;
  const auto file = temp.write("short.json", experiment().dump());
  for (const char* threads : {"1", "2"}) {
    const auto o = test_support::hystbench("track " + file.string() + " --threads " + threads + " --out " +
                                           (temp.path() / threads).string());
    ASSERT_EQ(o.code, 0) << o.output;
  }
  EXPECT_EQ(test_support::read(temp.path() / "1" / "table.csv"), test_support::read(temp.path() / "2" / "table.csv"));
}

TEST(TrackCommand, ImpossibleDesignIsRefusedBeforeAnythingIsWritten) {
  test_support::TempDir temp;
  nlohmann::json x = experiment();
  x["nominal"] = {{"p", 2}, {"q", 2}};  // a sampling zero outside the unit circle
  const auto file = temp.write("bad.json", x.dump());
  const auto out = temp.path() / "out";
  const auto o = test_support::hystbench("track " + file.string() + " --out " + out.string());
  EXPECT_EQ(o.code, 2) << o.output;
  EXPECT_TRUE(contains(o.output, "zero on or outside the unit circle")) << o.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace hystbench
