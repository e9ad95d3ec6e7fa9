// The closed loop: attenuation with an exact estimate, divergence reported
// as such, the same numbers on any thread count, and bad experiments
// stopped before anything is written.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <fstream>

#include "framework/control/control_run.hpp"
#include "framework/control/control_tables.hpp"
#include "framework/core/error.hpp"
#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

nlohmann::json experiment(nlohmann::json controllers, double seconds = 60.0) {
  return {{"duration_s", seconds},
          {"plant", {{"type", "mfc_beam"}}},
          {"controllers", std::move(controllers)},
          {"trials", 1},
          {"seed", 7}};
}

ControlResults run(const nlohmann::json& j) {
  const ControlExperiment x = ControlExperiment::from_json(j, "test");
  const ControlSetup setup = build_control_setup(x);
  return run_control(x, setup, [](int, int) {});
}

TEST(ControlLoop, FxnlmsWithTheExactEstimateAttenuatesByFortyDecibels) {
  const auto r = run(experiment({{{"name", "fxnlms"}, {"params", {{"mu", 0.003}}}}}));
  const auto& c = r.controllers[0];
  EXPECT_EQ(c.diverged_trials, 0);
  EXPECT_GE(c.truth.mean.attenuation_db, 40.0);
  // The measured error cannot go below the 30 dB noise floor.
  EXPECT_LT(c.measured.mean.attenuation_db, 31.0);
  EXPECT_GT(c.truth.mean.convergence_s, 0.5);
  EXPECT_LT(c.truth.mean.convergence_s, 10.0);
}

// Kuo and Morgan's offline identification: white noise through the path, an
// FIR adapted by NLMS. The beam rings for seconds, so a long FIR is needed
// for the phase at the disturbance; the estimate reports its own error.
TEST(ControlLoop, FirEstimateByLmsIsCloseInPhaseAndControls) {
  nlohmann::json j = experiment({{{"name", "fxnlms"}, {"params", {{"mu", 0.003}}}}}, 30.0);
  j["secondary"] = {{"type", "fir_lms"}, {"taps", 1024}, {"seconds", 60}};
  const ControlExperiment x = ControlExperiment::from_json(j, "test");
  const ControlSetup setup = build_control_setup(x);
  EXPECT_LT(std::abs(setup.estimates[0].error.phase_deg), 10.0);
  // 1024 taps cut the second mode's ringing (time constant 0.77 s) short: the
  // gain comes out low, which only rescales the step.
  EXPECT_GT(setup.estimates[0].error.gain_ratio, 0.5);
  EXPECT_LT(setup.estimates[0].error.gain_ratio, 1.5);
  const auto r = run_control(x, setup, [](int, int) {});
  EXPECT_EQ(r.controllers[0].diverged_trials, 0);
  EXPECT_GE(r.controllers[0].truth.mean.attenuation_db, 30.0);
}

TEST(ControlLoop, OffLeavesTheVibrationAsItIs) {
  const auto r = run(experiment({{{"name", "off"}}}));
  EXPECT_NEAR(r.controllers[0].truth.mean.efficiency_percent, 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(r.controllers[0].truth.mean.convergence_s));
  EXPECT_EQ(r.controllers[0].truth.never_converged, 1);
}

TEST(ControlLoop, TooLargeAStepDivergesAndIsReportedWithItsTime) {
  const nlohmann::json j =
      experiment({{{"label", "huge"}, {"name", "fxlms"}, {"params", {{"mu", 1.0}}}}}, 20.0);
  const auto r = run(j);
  const auto& c = r.controllers[0];
  EXPECT_EQ(c.diverged_trials, 1);
  EXPECT_TRUE(c.all_diverged());
  EXPECT_GT(c.earliest_divergence_s, 0.0);
  EXPECT_LT(c.earliest_divergence_s, 20.0);
  test_support::TempDir dir;
  const auto x = ControlExperiment::from_json(j, "test");
  write_control_tables(dir.path(), x, r);
  std::ifstream in(dir.path() / "table.md");
  const std::string table((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(table.find("diverged at"), std::string::npos) << table;
  EXPECT_EQ(table.find("nan"), std::string::npos) << table;
  EXPECT_EQ(table.find("NaN"), std::string::npos) << table;
}

TEST(ControlLoop, SameNumbersOnOneAndTwoThreads) {
  nlohmann::json j = experiment({{{"name", "vss_fxlms"}}, {{"name", "fxlms"}}}, 10.0);
  j["trials"] = 3;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = run(j);
  omp_set_num_threads(2);
  const auto two = run(j);
  omp_set_num_threads(threads);
  for (std::size_t c = 0; c < one.controllers.size(); ++c)
    for (int t = 0; t < 3; ++t) {
      EXPECT_EQ(one.controllers[c].trials[t].truth.rmse, two.controllers[c].trials[t].truth.rmse);
      EXPECT_EQ(one.controllers[c].trials[t].measured.mae, two.controllers[c].trials[t].measured.mae);
    }
  // Different noise seeds per trial.
  EXPECT_NE(one.controllers[0].trials[0].measured.rmse, one.controllers[0].trials[1].measured.rmse);
}

void expect_input_error(const nlohmann::json& j, const std::string& names) {
  try {
    const auto x = ControlExperiment::from_json(j, "exp.json");
    build_control_setup(x);
    FAIL() << "expected an InputError naming " << names;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(names), std::string::npos) << e.what();
  }
}

TEST(ControlExperimentFile, BadKeysAreNamed) {
  expect_input_error(experiment({{{"name", "fxnlms"}, {"params", {{"mu", -1}}}}}),
                     "controllers[0].params.mu");
  expect_input_error(experiment({{{"name", "fxlsm"}}}), "controllers[0].name");
  expect_input_error(experiment(nlohmann::json::array()), "controllers");
  auto j = experiment({{{"name", "off"}}});
  j["secondary"] = {{"type", "oracle"}};
  expect_input_error(j, "secondary.type");
  j = experiment({{{"name", "off"}}});
  j["actuator"] = {{"model", "hysteresis"}, {"parameters", {{"gain", 1}}}};
  expect_input_error(j, "actuator.parameters");
  j = experiment({{{"name", "off"}}});
  j["durration_s"] = 5;
  expect_input_error(j, "durration_s");
  j = experiment({{{"label", "a"}, {"name", "off"}}, {{"label", "a"}, {"name", "fxlms"}}});
  expect_input_error(j, "controllers[1].label");
  j = experiment({{{"name", "off"}}});
  j["step_sweep"] = {{"name", "vss_fxlms"}, {"param", "level"}, {"values", {1, 2}}};
  expect_input_error(j, "step_sweep.param");
  j["step_sweep"] = {{"name", "fxnlms"}, {"values", {0.01, -2}}};
  expect_input_error(j, "step_sweep.values[1].params.mu");
  j = experiment({{{"name", "off"}}}, 0.5);
  expect_input_error(j, "duration_s");
  j = experiment({{{"name", "off"}}});
  j["sample_rate_hz"] = 30;
  expect_input_error(j, "disturbance.frequency_hz");
  j = experiment({{{"name", "off"}}});
  j["plant"]["params"] = {{"sensor_at", 0.0}};
  expect_input_error(j, "plant.params");
  j = experiment({{{"name", "vss_kwong"}, {"params", {{"mu_min", 0.5}}}}});
  expect_input_error(j, "controllers[0].params.mu_min");
}

TEST(ControlCommand, BadExperimentExitsTwoAndWritesNothing) {
  test_support::TempDir dir;
  const auto file = dir.path() / "bad.json";
  std::ofstream(file) << experiment({{{"name", "vss_kwong"}, {"params", {{"mu_min", 0.5}}}}}).dump();
  const auto out = dir.path() / "out";
  const auto r = test_support::hystbench("control " + file.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("mu_min"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ControlCommand, WritesResultsAndListsControllers) {
  test_support::TempDir dir;
  const auto file = dir.path() / "short.json";
  nlohmann::json j = experiment({{{"name", "off"}}, {{"name", "vss_fxlms"}}}, 5.0);
  j["steady_s"] = 1;
  j["step_sweep"] = {{"name", "fxnlms"}, {"values", {0.003, 0.03}}};
  std::ofstream(file) << j.dump();
  const auto out = dir.path() / "out";
  const auto r = test_support::hystbench("control " + file.string() + " --out " + out.string() +
                                         " --trials 2");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"control.json", "table.md", "table.tex", "table.csv", "step_sweep.md",
                        "traces.csv", "spectrum.csv", "residual_error.gp", "step_size.gp"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  std::ifstream in(out / "control.json");
  const auto c = nlohmann::json::parse(in);
  ASSERT_EQ(c["controllers"].size(), 2u);
  EXPECT_EQ(c["controllers"][1]["label"], "vss_fxlms");
  EXPECT_TRUE(c["controllers"][1]["reconstructed"].get<bool>());
  EXPECT_TRUE(c["controllers"][1]["true"]["rmse"].contains("std"));
  EXPECT_EQ(c["step_sweep"]["runs"].size(), 2u);
  const auto listed = test_support::hystbench("list controllers");
  for (const char* name : {"fxlms", "fxnlms", "vss_fxlms", "vss_kwong", "vss_aboulnasr", "off"})
    EXPECT_NE(listed.output.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace hystbench
