// Fitting discovery models (framework/discovery/model_fit, fit_record): known
// parameters recovered from synthetic data, warm refits never worse than
// their start, bit-identical reruns, fit.json round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "framework/core/error.hpp"

#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_fit.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/model/model_problem.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

const nlohmann::json kExcitation = {
    {"sample_rate", 500},
    {"segments",
     {{{"type", "sine"}, {"frequency", 2}, {"amplitude", 50}, {"offset", 20}, {"duration", 1}},
      {{"type", "sine"}, {"frequency", 8}, {"amplitude", 60}, {"duration", 1}},
      {{"type", "sine"}, {"frequency", 30}, {"amplitude", 40}, {"duration", 1}}}}};

struct Synthetic {
  Model model;
  SyntheticData data;
  ModelData model_data;
};

Synthetic synthetic(const std::string& list, const nlohmann::json& values, double noise = 0.01) {
  const Model model = Model::parse(list);
  SyntheticData s = make_model_synthetic_data(model, values, kExcitation, noise, 7, "test");
  ModelData d(s.data, SignalScales::of(s.data));
  return {model, std::move(s), std::move(d)};
}

FitOptions quick_options() {
  FitOptions o;
  o.restarts = 2;
  o.evaluations = 3000;
  o.local_evaluations = 1500;
  o.seed = 11;
  return o;
}

TEST(ModelFit, RecoversAKnownDynamicModelToTheNoiseFloor) {
  const auto s = synthetic("offset,msd", {{"gain", 0.5}, {"offset.c0", 3.0},
                                          {"msd.period", 0.02}, {"msd.zeta", 0.2}});
  const FitResult r = fit_model(s.model, s.model_data, quick_options());
  const FitErrors e = fit_errors(r.model, r.x, s.model_data);
  const double sd = s.data.truth["noise"]["sd"];
  EXPECT_LT(e.rmse_estimation, 1.05 * sd);
  const auto values = r.model.physical_values(r.x, s.model_data.scales);
  EXPECT_NEAR(values["gain"].get<double>(), 0.5, 0.01);
  EXPECT_NEAR(values["msd.period"].get<double>(), 0.02, 0.0005);
  EXPECT_NEAR(values["offset.c0"].get<double>(), 3.0, 0.1);
}

TEST(ModelFit, SameSeedSameBitsAndEveryStartIsRecorded) {
  const auto s = synthetic("asymmetry", {{"gain", 0.5}, {"asymmetry.d2", 0.002}});
  auto o = quick_options();
  o.evaluations = 500;
  o.local_evaluations = 200;
  const FitResult a = fit_model(s.model, s.model_data, o);
  const FitResult b = fit_model(s.model, s.model_data, o);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.sse, b.sse);
  EXPECT_EQ(a.start_sse.size(), 2u);
  // Each restart spends its global share, the polish may converge sooner.
  EXPECT_GE(a.evaluations, 2 * 500);
  EXPECT_LE(a.evaluations, 2 * (500 + 200));
}

TEST(ModelFit, WarmRefitOfANewEffectStartsFromTheCurrentFitAndFindsIt) {
  const auto s = synthetic("asymmetry", {{"gain", 0.5}, {"asymmetry.d2", 0.004}}, 0.005);
  const Model base = Model::parse("none");
  auto o = quick_options();
  const FitResult start = fit_model(base, s.model_data, o);
  const Model extended = base.with("asymmetry");
  const Eigen::VectorXd x0 = extended.carry_over(base, start.x);
  ModelProblem problem(extended, s.model_data);
  EXPECT_EQ(problem.sse(x0), start.sse);  // neutral effect: exactly the same model
  const FitResult r = refit_warm(extended, s.model_data, x0, extended.parameters_of("asymmetry"), o);
  EXPECT_LE(r.sse, start.sse);
  EXPECT_LT(fit_errors(r.model, r.x, s.model_data).rmse_estimation,
            1.05 * s.data.truth["noise"]["sd"].get<double>());
}

TEST(ModelFit, FitRecordRoundTripsBitForBit) {
  const auto s = synthetic("hysteresis,msd", {{"gain", 0.5}, {"hysteresis.A", 0.1},
                                              {"hysteresis.beta", 0.01}, {"hysteresis.gamma", 0.002},
                                              {"msd.period", 0.03}, {"msd.zeta", 0.3}});
  test_support::TempDir dir;
  DataSource source;
  source.path = "data.csv";
  source.u_unit = "V";
  source.y_unit = "µm";
  const Eigen::VectorXd x = s.model.from_physical(
      s.data.truth["parameters"], s.model_data.scales, "truth");
  const FitRecord r = make_fit_record(s.model, x, s.model_data, source, HoldoutSpec{}, 5);
  std::ofstream(dir.path() / "fit.json") << r.to_json().dump(2);
  const FitRecord back = FitRecord::read(dir.path() / "fit.json");
  EXPECT_EQ(back.model.text(), "hysteresis,msd");
  EXPECT_EQ(back.x, x);
  EXPECT_EQ(back.scales.y, s.model_data.scales.y);
  EXPECT_EQ(back.data.y_unit, "µm");
  EXPECT_EQ(r.parameters_json()[0]["unit"], "µm/V");
}

// A diverged fit's errors are infinite; JSON writes them as null, and a
// checkpoint read back must not turn them into a perfect 0.
TEST(ModelFit, ErrorsOfADivergedFitStayInfiniteThroughJson) {
  FitErrors diverged;
  diverged.stable = false;
  diverged.n_estimation = 80;
  diverged.n_heldout = 20;
  diverged.rmse_estimation = diverged.rmse_heldout = std::numeric_limits<double>::infinity();
  const FitErrors back = FitErrors::from_json(nlohmann::json::parse(diverged.to_json().dump()));
  EXPECT_FALSE(back.stable);
  EXPECT_EQ(back.rmse_estimation, std::numeric_limits<double>::infinity());
  EXPECT_EQ(back.rmse_heldout, std::numeric_limits<double>::infinity());

  FitErrors nothing_held_out = diverged;
  nothing_held_out.n_heldout = 0;
  EXPECT_EQ(FitErrors::from_json(nothing_held_out.to_json()).rmse_heldout, 0.0);
}

TEST(ModelFit, FitRecordKeepsACausalInputHoldAndReadsOldFilesAsSpline) {
  const auto s = synthetic("feedback_hysteresis",
                           {{"gain", 0.5}, {"feedback_hysteresis.period", 0.05}, {"feedback_hysteresis.zeta", 0.3},
                            {"feedback_hysteresis.alpha", 0.5}, {"feedback_hysteresis.beta_gamma", 0.01},
                            {"feedback_hysteresis.beta_delta", 0.0}});
  test_support::TempDir dir;
  const Eigen::VectorXd x = s.model.from_physical(s.data.truth["parameters"], s.model_data.scales, "truth");
  const FitRecord spline = make_fit_record(s.model, x, s.model_data, DataSource{}, HoldoutSpec{}, 5);
  EXPECT_FALSE(spline.to_json().contains("input_hold")) << "default fits are written as before";
  std::ofstream(dir.path() / "spline.json") << spline.to_json().dump(2);
  EXPECT_EQ(FitRecord::read(dir.path() / "spline.json").model.input_hold(), InputHold::Spline);

  Model linear = s.model;
  linear.set_input_hold(InputHold::Linear);
  const FitRecord r = make_fit_record(linear, x, s.model_data, DataSource{}, HoldoutSpec{}, 5);
  EXPECT_EQ(r.to_json()["input_hold"], "linear");
  std::ofstream(dir.path() / "linear.json") << r.to_json().dump(2);
  EXPECT_EQ(FitRecord::read(dir.path() / "linear.json").model.input_hold(), InputHold::Linear);

  nlohmann::json bad = r.to_json();
  bad["input_hold"] = "cubic";
  std::ofstream(dir.path() / "bad.json") << bad.dump(2);
  try {
    FitRecord::read(dir.path() / "bad.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json input_hold: unknown input hold 'cubic'; valid: spline, "
                                         "linear, zoh"),
              std::string::npos)
        << e.what();
  }
}

TEST(ModelFit, BrokenFitFilesNameTheProblem) {
  test_support::TempDir dir;
  std::ofstream(dir.path() / "a.json") << R"({"format": "hystbench-fit/1", "model": "msd",
      "scales": {"u": 1, "y": 1}, "data": {}, "parameters": [{"name": "gain", "normalised": 1}]})";
  try {
    FitRecord::read(dir.path() / "a.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing parameter 'msd.period'"), std::string::npos);
  }
  std::ofstream(dir.path() / "b.json") << R"({"model": "msd"})";
  EXPECT_THROW(FitRecord::read(dir.path() / "b.json"), InputError);
}

TEST(ModelFit, SteadyStateSimulationScoresTheLastOfRepeatedPeriods) {
  const auto s = synthetic("msd", {{"gain", 1.0}, {"msd.period", 0.05}, {"msd.zeta", 0.3}});
  Eigen::VectorXd x = s.model.neutral();
  x[1] = 0.05;
  x[2] = 0.3;
  Eigen::VectorXd once, three, four;
  ASSERT_TRUE(simulate_physical(s.model, x, s.model_data, once));
  ASSERT_TRUE(simulate_physical(s.model, x, s.model_data, three, 3));
  ASSERT_TRUE(simulate_physical(s.model, x, s.model_data, four, 4));
  ASSERT_EQ(three.size(), once.size());
  // From rest, the first samples carry a transient that the periodic steady
  // state does not have; after it has died out, both agree.
  EXPECT_GT((three - once).head(50).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_NEAR(three[three.size() - 1], once[once.size() - 1], 1e-9);
  EXPECT_LT((three - four).cwiseAbs().maxCoeff(), 1e-9);
}

// A record of n samples whose input is a sine of amplitude amp(k).
template <class Amplitude>
ModelData sine_record(Eigen::Index n, Amplitude amp) {
  ModelData d;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, double(n - 1) * 1e-3);
  d.u.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) d.u[k] = amp(k) * std::sin(0.37 * double(k));
  d.y = d.u;
  d.sample_time = 1e-3;
  d.estimation = Eigen::VectorXd::Ones(n);
  return d;
}

TEST(ModelFit, GlobalStagesSeeTheWholeRecordWhenItsHeadMissesTheLargeStrokes) {
  FitOptions o;
  o.screening_samples = 1000;
  // Steady amplitude: the head stands for the record.
  EXPECT_EQ(screening_length(sine_record(4000, [](auto) { return 1.0; }), o), 1000);
  // A handful of spikes at the end (under 0.5 % of the samples) changes nothing.
  ModelData spiky = sine_record(4000, [](auto) { return 1.0; });
  for (Eigen::Index k = 3990; k < 4000; ++k) spiky.u[k] = 10.0;
  EXPECT_EQ(screening_length(spiky, o), 1000);
  // An arrow, its amplitude growing tenfold: the head holds only small strokes.
  const auto arrow = sine_record(4000, [](Eigen::Index k) { return 0.1 + double(k) / 4000.0; });
  EXPECT_EQ(screening_length(arrow, o), 4000);
  // A record no longer than the screening length is screened whole.
  o.screening_samples = 5000;
  EXPECT_EQ(screening_length(arrow, o), 4000);
  o.screening_samples = 0;
  EXPECT_EQ(screening_length(arrow, o), 4000);
}

}  // namespace
}  // namespace hystbench
