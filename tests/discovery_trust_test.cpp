// What makes a discovery result trustworthy (framework/discovery):
// parameter standard errors against the closed form of a linear regression,
// effects that do nothing flagged as neutral, the completeness verdict, and
// the close-call rule of a diagnosis.
#include <gtest/gtest.h>

#include "framework/core/eigen.hpp"
#include <cmath>
#include <random>

#include "framework/discovery/completeness.hpp"
#include "framework/discovery/diagnosis.hpp"
#include "framework/discovery/model_check.hpp"
#include "framework/discovery/parameter_uncertainty.hpp"
#include "framework/discovery/resonance.hpp"

namespace hystbench {
namespace {

// y = 2u + offset + noise(σ ≈ 0.05), u a 3 Hz sine at 1 kHz; scales 1 so
// normalised and physical values agree. The noise is made orthogonal to u
// and to a constant, so the least-squares fit is exactly (2, offset).
ModelData linear_data(double offset, int n = 2000, unsigned seed = 3) {
  Measurement m;
  m.sample_time = 1e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * (n - 1));
  m.u = (2 * M_PI * 3.0 * m.t.array()).sin().matrix();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 0.05);
  Eigen::VectorXd noise(n);
  for (int k = 0; k < n; ++k) noise[k] = normal(rng);
  Eigen::MatrixXd X(n, 2);
  X << m.u, Eigen::VectorXd::Ones(n);
  noise -= X * X.colPivHouseholderQr().solve(noise);
  m.y = 2.0 * m.u + Eigen::VectorXd::Constant(n, offset) + noise;
  return ModelData(m, {});
}

// The least-squares gain and offset, and their closed-form standard errors.
struct LinearFit {
  Eigen::Vector2d x, sd;
};
LinearFit least_squares(const ModelData& d) {
  Eigen::MatrixXd X(d.size(), 2);
  X.col(0) = d.u;
  X.col(1).setOnes();
  LinearFit f;
  f.x = X.colPivHouseholderQr().solve(d.y);
  const double s2 = (d.y - X * f.x).squaredNorm() / double(d.size() - 2);
  f.sd = (s2 * (X.transpose() * X).inverse()).diagonal().cwiseSqrt();
  return f;
}

TEST(ParameterUncertainty, MatchesTheClosedFormOfALinearRegression) {
  const ModelData d = linear_data(0.3);
  const Model model = Model::parse("offset");
  const LinearFit f = least_squares(d);
  const ParameterUncertainty u = parameter_uncertainty(model, f.x, d);
  ASSERT_TRUE(u.available);
  EXPECT_NEAR(u.sd[0], f.sd[0], 1e-3 * f.sd[0]);
  EXPECT_NEAR(u.sd[1], f.sd[1], 1e-3 * f.sd[1]);
  // A sine over whole periods is orthogonal to a constant.
  EXPECT_NEAR(u.correlation(0, 1), 0.0, 0.01);
}

TEST(ParameterUncertainty, AParameterTheDataCannotSeeIsUndetermined) {
  // A drift with every sample at t = 0 changes nothing: its parameter is
  // undetermined while the others stay determined.
  ModelData d = linear_data(0.3);
  const Model model = Model::parse("offset,drift");
  Eigen::VectorXd x = model.neutral();
  x[0] = 2.0;
  x[1] = 0.3;
  // Without time the drift is invisible: every sample at t = 0.
  d.t.setZero();
  const ParameterUncertainty u = parameter_uncertainty(model, x, d);
  ASSERT_TRUE(u.available);
  EXPECT_TRUE(std::isinf(u.sd[2]));
  EXPECT_TRUE(std::isfinite(u.sd[0]));
}

TEST(ModelCheck, AnEffectWithinNoiseOfNeutralIsFlagged) {
  for (const double offset : {0.0, 0.3}) {
    const ModelData d = linear_data(offset);
    const LinearFit f = least_squares(d);
    const ModelCheck c = check_model(Model::parse("offset"), f.x, d, "V", "µm");
    EXPECT_EQ(c.neutral("offset"), offset == 0.0) << offset;
    EXPECT_EQ(c.parameters[1].name, "offset.c0");
    EXPECT_NEAR(c.parameters[1].value, offset, 1e-12);
    EXPECT_EQ(c.warnings().empty(), offset != 0.0);
  }
}

TEST(ModelCheck, ParametersOnABoundAndDelaysInSeconds) {
  const ModelData d = linear_data(0.3);
  const Model model = Model::parse("delay,offset");
  Eigen::VectorXd x = model.neutral();
  x[0] = 2.0;                                   // gain
  x[model.parameters_of("delay")[0]] = 20.0;    // the upper bound of d (samples)
  x[model.parameters_of("offset")[0]] = 0.3;
  const ModelCheck c = check_model(model, x, d, "V", "µm");
  const auto& delay = c.parameters[model.parameters_of("delay")[0]];
  EXPECT_TRUE(delay.at_bound);
  EXPECT_DOUBLE_EQ(delay.seconds, 20.0 * 1e-3);
  EXPECT_FALSE(c.parameters[model.parameters_of("offset")[0]].at_bound);
  EXPECT_EQ(c.effects[0].at_bound, std::vector<std::string>{"delay.d"});
}

TEST(ModelCheck, AShapeParameterNeitherKeepsAnEffectOnNorSitsOnABound) {
  // Without a limit, saturation does nothing whatever its softness, which
  // the data then cannot determine; softness 0 is a hard clip, a shape of
  // its own, not the edge of a range too narrow.
  const ModelData d = linear_data(0.0);
  const Model model = Model::parse("saturation");
  for (const double softness : {0.0, 0.8}) {
    Eigen::VectorXd x(3);
    x << least_squares(d).x[0], 0.0, softness;
    const ModelCheck off = check_model(model, x, d, "V", "µm");
    EXPECT_TRUE(off.neutral("saturation")) << softness;
    EXPECT_FALSE(off.parameters[2].at_bound) << softness;
    // Data bent by that limit (the same noise): at the truth the effect is on.
    x[1] = 0.5;
    ModelData bent = d;
    Eigen::VectorXd y;
    ASSERT_TRUE(model.simulate(x, d, y));
    bent.y = y + (d.y - 2.0 * d.u);
    EXPECT_FALSE(check_model(model, x, bent, "V", "µm").neutral("saturation")) << softness;
  }
}

// Normalised parameters of `model` from physical values with unit scales.
Eigen::VectorXd values_of(const Model& model, const nlohmann::json& values) {
  return model.from_physical(values, SignalScales{}, "test");
}

TEST(Resonance, AMassSpringDamperResonatesAtItsDampedPeak) {
  const Model model = Model::parse("msd");
  const auto x = values_of(model, {{"gain", 1.0}, {"msd.period", 0.025}, {"msd.zeta", 0.1}});
  const auto r = resonances(model, x, 1e-3);
  ASSERT_EQ(r.size(), 1u);
  // Peak of a second-order system: f_n·sqrt(1 − 2ζ²) = 40·0.98995 = 39.6 Hz
  // (the bilinear discretisation moves it by well under 1 %).
  EXPECT_NEAR(r[0].hz, 39.6, 0.6);
  // Peak gain 1/(2ζ sqrt(1 − ζ²)) = 5.03.
  EXPECT_NEAR(r[0].peak_gain, 5.03, 0.3);
}

TEST(Resonance, ASecondModeOnTheFirstModesFrequencyIsRecognised) {
  const Model model = Model::parse("msd,second_mode");
  const nlohmann::json base = {{"gain", 1.0}, {"msd.period", 0.025}, {"msd.zeta", 0.1},
                               {"second_mode.participation", 0.3}, {"second_mode.zeta", 0.05}};
  auto on_top = base, apart = base;
  on_top["second_mode.log10_f"] = std::log10(40.0);
  apart["second_mode.log10_f"] = std::log10(250.0);
  const std::string shared =
      shared_resonance(model, values_of(model, on_top), 1e-3, "second_mode");
  EXPECT_NE(shared.find("as msd does"), std::string::npos) << shared;
  EXPECT_EQ(shared_resonance(model, values_of(model, apart), 1e-3, "second_mode"), "");
}

// compare_signals-like residual statistics for the completeness tests.
Comparison where(double sigma, double p_value, int outside) {
  Comparison c;
  c.noise_floor.sigma = sigma;
  c.residual.ljung_box.p_value = p_value;
  c.residual.ccf.outside = outside;
  c.residual.ccf.lags.assign(51, 0);
  for (const auto& [segment, rmse] : {std::pair{"a", 1.0}, {"b", 3.0}}) {
    SegmentErrors s{segment, "estimation", {}};
    s.metrics.rmse = rmse;
    c.by_segment.push_back(s);
  }
  return c;
}

FitErrors errors(double estimation, double heldout) {
  FitErrors e;
  e.stable = true;
  e.n_estimation = 1000;
  e.n_heldout = heldout > 0 ? 300 : 0;
  e.rmse_estimation = estimation;
  e.rmse_heldout = heldout;
  return e;
}

TEST(Completeness, WhiteAtTheFloorOnBothPartsIsComplete) {
  const Completeness c = assess_completeness(errors(1.05, 1.1), where(1.0, 0.3, 1));
  EXPECT_TRUE(c.complete);
  EXPECT_EQ(c.kind, "white_at_floor");
  EXPECT_EQ(c.worst_segment, "b");
  EXPECT_DOUBLE_EQ(c.worst_segment_rmse_over_sigma, 3.0);
}

TEST(Completeness, AHeldOutErrorAboveTheFloorIsNotComplete) {
  const Completeness c = assess_completeness(errors(1.05, 5.0), where(1.0, 0.3, 1));
  EXPECT_FALSE(c.complete);
  EXPECT_EQ(c.kind, "systematic");
  EXPECT_NE(c.reason.find("5 σ held out"), std::string::npos) << c.reason;
}

TEST(Completeness, AtTheFloorButColouredOrCorrelatedWithTheInput) {
  EXPECT_EQ(assess_completeness(errors(1.0, 1.0), where(1.0, 0.001, 0)).kind, "coloured_at_floor");
  EXPECT_EQ(assess_completeness(errors(1.0, 1.0), where(1.0, 0.5, 3)).kind, "coloured_at_floor");
  EXPECT_FALSE(assess_completeness(errors(1.0, 1.0), where(1.0, 0.5, 3)).complete);
}

TEST(Completeness, WithoutANoiseEstimateNothingIsClaimed) {
  const Completeness c = assess_completeness(errors(1.0, 1.0), where(0.0, 0.5, 0));
  EXPECT_FALSE(c.complete);
  EXPECT_EQ(c.kind, "no_noise_estimate");
}

TEST(Completeness, AnErrorWellBelowTheNoiseEstimateMeansTheEstimateIsWrong) {
  // Both parts at or under the floor, one well under it: nothing is judged.
  const Completeness c = assess_completeness(errors(1.1, 0.39), where(1.01, 0.5, 0));
  EXPECT_FALSE(c.complete);
  EXPECT_EQ(c.kind, "noise_estimate_too_high");
  EXPECT_NE(c.reason.find("held-out error is 0.386 σ"), std::string::npos) << c.reason;
  // Silverbox-like: 1.43 mV on the estimation part, 0.39 mV held out, against
  // an estimate of 1.01 mV: still systematic, and the reason says the
  // estimate is too high.
  const Completeness s = assess_completeness(errors(1.43, 0.39), where(1.01, 0.5, 0));
  EXPECT_EQ(s.kind, "systematic");
  EXPECT_NE(s.reason.find("noise estimate is too high"), std::string::npos) << s.reason;
  // Just under the estimate, within the tolerance, is still at the floor.
  EXPECT_TRUE(assess_completeness(errors(0.9, 0.95), where(1.0, 0.3, 1)).complete);
}

// A diagnosis whose candidates are given: (effect, ΔBIC, held-out RMSE).
Diagnosis planted(const std::vector<std::tuple<std::string, double, double>>& candidates) {
  Diagnosis d{Model::parse("hysteresis"), Eigen::VectorXd(), errors(1.0, 1.0)};
  for (const auto& [effect, delta_bic, heldout] : candidates) {
    Candidate c{effect, Model::parse("hysteresis"), Eigen::VectorXd(), errors(0.5, heldout)};
    c.delta_bic = delta_bic;
    c.significant = delta_bic <= -10;
    d.candidates.push_back(c);
  }
  return d;
}

TEST(CloseCall, TheHeldOutErrorDecidesWhenItDisagreesWithBic) {
  // On one record arx won on BIC while delay, with a quarter of the
  // parameters, had the clearly better held-out error.
  Diagnosis d = planted({{"arx", -37516, 0.339}, {"delay", -36322, 0.238}, {"creep", 5, 0.9}});
  decide(d, DiagnoseOptions{});
  EXPECT_EQ(d.verdict, "delay");
  EXPECT_TRUE(d.close_call.close);
  EXPECT_EQ(d.close_call.runner_up, "arx");
  EXPECT_NE(d.close_call.reason.find("held-out error decides"), std::string::npos);
}

TEST(CloseCall, BicDecidesWhenTheHeldOutErrorsAreWithinTheGain) {
  Diagnosis d = planted({{"arx", -500, 0.500}, {"delay", -400, 0.498}});
  decide(d, DiagnoseOptions{});
  EXPECT_EQ(d.verdict, "arx");
  EXPECT_TRUE(d.close_call.close);
  EXPECT_EQ(d.close_call.runner_up, "delay");
}

TEST(CloseCall, ARunnerUpWithinTheMarginIsReported) {
  Diagnosis d = planted({{"arx", -500, 0.40}, {"delay", -495, 0.45}});
  decide(d, DiagnoseOptions{});
  EXPECT_EQ(d.verdict, "arx");
  EXPECT_TRUE(d.close_call.close);
  EXPECT_EQ(d.close_call.runner_up, "delay");
  Diagnosis clear = planted({{"arx", -500, 0.40}, {"delay", -100, 0.45}});
  decide(clear, DiagnoseOptions{});
  EXPECT_EQ(clear.verdict, "arx");
  EXPECT_FALSE(clear.close_call.close);
}

TEST(CloseCall, NothingSignificantIsNone) {
  Diagnosis d = planted({{"arx", -5, 0.40}});
  decide(d, DiagnoseOptions{});
  EXPECT_EQ(d.verdict, "none");
  EXPECT_EQ(d.winner(), nullptr);
}

}  // namespace
}  // namespace hystbench
