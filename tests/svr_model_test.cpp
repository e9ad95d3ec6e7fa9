// The SVR Hammerstein-like model: ARX orders by AIC, the epsilon-SVR against
// its closed form, the whole model's free run, and the JSON round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/rng.hpp"
#include "framework/io/measurement.hpp"
#include "framework/svr/svr_model.hpp"
#include "framework/svr/svr_stream.hpp"
#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

// y(k) = 1.5 y(k-1) - 0.7 y(k-2) + v(k) + 0.5 v(k-1) + noise: A(z) has its
// roots at 0.75 +- 0.37i, inside the unit circle.
void arx_data(Eigen::VectorXd& v, Eigen::VectorXd& y, double noise) {
  Rng rng(7);
  const int n = 3000;
  v.resize(n);
  y.setZero(n);
  for (int k = 0; k < n; ++k) v[k] = rng.normal();
  for (int k = 0; k < n; ++k) {
    y[k] = v[k] + noise * rng.normal();
    if (k >= 1) y[k] += 1.5 * y[k - 1] + 0.5 * v[k - 1];
    if (k >= 2) y[k] -= 0.7 * y[k - 2];
  }
}

TEST(ArxFit, AicPicksTheTrueOrdersAndLeastSquaresTheCoefficients) {
  Eigen::VectorXd v, y;
  arx_data(v, y, 0.01);
  const ArxSelection s = select_arx(v, y, 4, 4, "test");
  EXPECT_EQ(s.grid.size(), 16u);
  EXPECT_EQ(s.best.p, 2);
  EXPECT_EQ(s.best.q, 2);
  EXPECT_TRUE(s.best.stable);
  EXPECT_NEAR(s.best.a[0], -1.5, 1e-3);
  EXPECT_NEAR(s.best.a[1], 0.7, 1e-3);
  EXPECT_NEAR(s.best.b[0], 1.0, 1e-3);
  EXPECT_NEAR(s.best.b[1], 0.5, 1e-3);
  // Without noise the output-error simulation is the data.
  arx_data(v, y, 0.0);
  const ArxFit exact = fit_arx(v, y, 2, 2, 2, "test");
  EXPECT_LT((exact.simulate(v) - y).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(ArxFit, UnstableFitsAreRejected) {
  Eigen::VectorXd v = Eigen::VectorXd::Ones(200), y(200);
  y[0] = 1.0;
  for (int k = 1; k < 200; ++k) y[k] = 1.05 * y[k - 1] + v[k];  // pole at 1.05
  EXPECT_FALSE(fit_arx(v, y, 1, 1, 1, "test").stable);
  try {
    select_arx(v, y, 1, 1, "stage 2");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stable"), std::string::npos) << e.what();
  }
}

// f(x) = sum_i c_i exp(-|x_i - x|^2 / (2 sigma^2)) - rho, from the model file.
double closed_form(const nlohmann::json& j, const Eigen::VectorXd& x) {
  double f = -j["rho"].get<double>();
  const double gamma = 1.0 / (2.0 * std::pow(j["sigma"].get<double>(), 2));
  for (std::size_t i = 0; i < j["coefficients"].size(); ++i) {
    Eigen::VectorXd sv = Eigen::VectorXd::Zero(x.size());
    for (const auto& node : j["support_vectors"][i]) sv[node[0].get<int>() - 1] = node[1].get<double>();
    f += j["coefficients"][i].get<double>() * std::exp(-gamma * (sv - x).squaredNorm());
  }
  return f;
}

TEST(SvrRegressor, PredictsItsClosedFormAndFitsSmallData) {
  Eigen::MatrixXd x(5, 2);
  x << 0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5;
  Eigen::VectorXd y(5);
  y << 0.0, 1.0, -1.0, 0.5, 0.2;
  const SvrRegressor svr = SvrRegressor::train(x, y, {0.01, 1000.0, 0.7}, "test");
  const nlohmann::json j = svr.to_json();
  EXPECT_NEAR(j["gamma"].get<double>(), 1.0 / (2 * 0.49), 1e-15);
  for (int r = 0; r < 5; ++r) {
    EXPECT_NEAR(svr.predict(x.row(r).transpose()), closed_form(j, x.row(r).transpose()), 1e-12) << r;
    // A large C keeps every target inside the tube (plus the solver's tolerance).
    EXPECT_NEAR(svr.predict(x.row(r).transpose()), y[r], 0.01 + 2e-3) << r;
  }
  Eigen::VectorXd off(2);
  off << 0.3, 0.8;
  EXPECT_NEAR(svr.predict(off), closed_form(j, off), 1e-12);
}

TEST(SvrRegressor, InvalidHyperparametersAreInputErrors) {
  Eigen::MatrixXd x = Eigen::MatrixXd::Random(4, 2);
  Eigen::VectorXd y = Eigen::VectorXd::Random(4);
  for (const SvrHyperparameters& h : {SvrHyperparameters{0.01, 0.0, 1.0}, SvrHyperparameters{-0.1, 1.0, 1.0},
                                      SvrHyperparameters{0.01, 1.0, 0.0}})
    EXPECT_THROW(SvrRegressor::train(x, y, h, "test"), InputError);
}

// A rate-independent loop to learn: a play operator on a sine, sampled
// finely (what stage 1 sees at 1 Hz).
void loop_data(Eigen::VectorXd& x, Eigen::VectorXd& y, int n) {
  x.resize(n);
  y.resize(n);
  double state = 0.0;
  for (int k = 0; k < n; ++k) {
    x[k] = 75.0 + 75.0 * std::sin(2.0 * M_PI * k / 200.0);
    state = std::clamp(state, x[k] - 10.0, x[k] + 10.0);
    y[k] = 0.1 * state;
  }
}

// The loop as a measurement file sampled at 1 kHz.
void write_loop_record(const std::filesystem::path& path, int n) {
  Measurement m;
  loop_data(m.u, m.y, n);
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * 1e-3);
  write_measurement(path, m);
}

TEST(SvrHammerstein, LearnsALoopAndRoundTripsThroughJson) {
  Eigen::VectorXd x, y;
  loop_data(x, y, 600);
  SvrHammerstein model = SvrHammerstein::fit_stage1(x, y, {2, 2}, {0.001, 10.0, 1.0}, "test");
  const Eigen::VectorXd free = model.simulate(x, y);
  const double rms = std::sqrt((free - y).squaredNorm() / double(y.size()));
  EXPECT_LT(rms, 0.05 * (y.maxCoeff() - y.minCoeff())) << "free-run RMSE " << rms;
  const Eigen::VectorXd one = model.one_step(x, y);
  EXPECT_LT((one - y).cwiseAbs().maxCoeff(), 0.1 * (y.maxCoeff() - y.minCoeff()));
  // A stage 2 on the same record, then the file round trip.
  model.fit_stage2(x, y, 2, 2, "test");
  ASSERT_TRUE(model.arx().has_value());
  const std::string text = model.to_json().dump();
  const SvrHammerstein loaded = SvrHammerstein::from_json(nlohmann::json::parse(text), "test");
  const Eigen::VectorXd a = model.simulate(x, y), b = loaded.simulate(x, y);
  for (Eigen::Index k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], b[k]) << k;
}

// The rate regressor: tanh of the scaled input's step over the training
// record's largest step, so that step gives exactly tanh(1) and the sign
// follows the direction of the input.
TEST(SvrHammerstein, InputRateIsOneMoreRegressorScaledByTheLargestStep) {
  Eigen::VectorXd x, y;
  loop_data(x, y, 600);
  Eigen::MatrixXd rows;
  Eigen::VectorXd targets;
  SvrHammerstein::regression_rows(x, y, {2, 2, true}, rows, targets);
  ASSERT_EQ(rows.cols(), 7);
  EXPECT_EQ(rows.rows(), 600 - 3);  // rows predict samples 3 .. 599
  EXPECT_DOUBLE_EQ(rows.col(6).cwiseAbs().maxCoeff(), std::tanh(1.0));
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    const Eigen::Index k = r + 2;
    const double dx = x[k] - x[k - 1];
    if (std::abs(dx) > 1e-9) {
      ASSERT_EQ(rows(r, 6) > 0, dx > 0) << k;
    }
    if (r + 1 < rows.rows()) {
      ASSERT_EQ(rows(r, 0), rows(r + 1, 1)) << "x(k) is x(k-1) of the next row";
    }
  }
  // Fitted, written and read back: the same free run bit for bit, and a
  // file whose lags drop the rate no longer matches the regressor.
  const SvrHammerstein model = SvrHammerstein::fit_stage1(x, y, {2, 2, true}, {0.001, 10.0, 1.0}, "test");
  EXPECT_EQ(model.regressor().dimension(), 7);
  nlohmann::json j = nlohmann::json::parse(model.to_json().dump());
  const Eigen::VectorXd a = model.simulate(x, y), b = SvrHammerstein::from_json(j, "test").simulate(x, y);
  for (Eigen::Index k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], b[k]) << k;
  const double rms = std::sqrt((a - y).squaredNorm() / double(y.size()));
  EXPECT_LT(rms, 0.05 * (y.maxCoeff() - y.minCoeff())) << "free-run RMSE " << rms;
  j["lags"].erase("input_rate");
  try {
    SvrHammerstein::from_json(j, "model.json");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(test_support::contains(e.what(), "model.json.svr.dimension")) << e.what();
  }
}

// A loop's stream with the rate regressor: from rest, the first input's
// row is built by hand (the rate from 0 V to u, scaled by the model file's
// rate_step); a trial of the front moves nothing, so it equals the step
// that follows it, sample after sample.
TEST(SvrHammerstein, StreamTrialWithTheRateLeavesTheStateAlone) {
  Eigen::VectorXd x, y;
  loop_data(x, y, 600);
  const SvrHammerstein model = SvrHammerstein::fit_stage1(x, y, {2, 2, true}, {0.001, 10.0, 1.0}, "test");
  SvrStream stream(model);
  const double u = 40.0, step = model.to_json()["rate_step"].get<double>();
  const double at_rest = model.input_scale().to_unit(0.0), x0 = model.input_scale().to_unit(u);
  Eigen::VectorXd row(7);
  row << x0, at_rest, at_rest, Eigen::Vector3d::Constant(model.output_scale().to_unit(0.0)),
      std::tanh((x0 - at_rest) / step);
  EXPECT_GT(row[6], 0.0);
  EXPECT_EQ(stream.predict_front(u), model.output_scale().from_unit(model.regressor().predict(row)));
  for (Eigen::Index k = 0; k < 300; ++k) {
    const double trial = stream.predict_front(x[k]), again = stream.predict_front(x[k]);
    ASSERT_EQ(trial, again) << k;
    ASSERT_EQ(trial, stream.step_front(x[k])) << k;
  }
}

// Stage 2 on the one-step prediction instead of the free run: a different
// input to the ARX fit, so different coefficients.
TEST(SvrHammerstein, CouplingChoosesWhatStageTwoIsFittedOn) {
  Eigen::VectorXd x, y;
  loop_data(x, y, 600);
  SvrHammerstein free = SvrHammerstein::fit_stage1(x, y, {2, 2}, {0.01, 10.0, 1.0}, "test");
  SvrHammerstein one = free;
  const ArxSelection a = free.fit_stage2(x, y, 2, 2, "test");
  const ArxSelection b = one.fit_stage2(x, y, 2, 2, "test", SvrCoupling::OneStep);
  const ArxSelection c = free.fit_stage2(x, y, 2, 2, "test", SvrCoupling::FreeRun);
  auto same = [](const ArxFit& f, const ArxFit& g) { return f.b.size() == g.b.size() && f.b == g.b; };
  EXPECT_TRUE(same(a.best, c.best));
  EXPECT_FALSE(same(a.best, b.best));
}

TEST(SvrHammerstein, TooShortOrConstantRecordsAreInputErrors) {
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(6, 0, 1), y = x;
  EXPECT_THROW(SvrHammerstein::fit_stage1(x, y, {4, 4}, {}, "test"), InputError);
  x = Eigen::VectorXd::LinSpaced(50, 0, 1);
  y = Eigen::VectorXd::Constant(50, 2.0);
  EXPECT_THROW(SvrHammerstein::fit_stage1(x, y, {4, 4}, {}, "test"), InputError);
  EXPECT_THROW(SvrHammerstein::from_json({{"model", "other"}}, "file.json"), InputError);
}

}  // namespace
}  // namespace hystbench

namespace hystbench {
namespace {

// A problem fitness is a pure function of the candidate: the same
// hyperparameters score the same, and the validation error is finite.
TEST(SvrHyperparameters, FitnessIsDeterministicForEveryValidation) {
  test_support::TempDir dir;
  write_loop_record(dir.path() / "train.csv", 400);
  for (const char* fitness : {"blocked_cv", "libsvm_cv", "freerun_holdout"}) {
    const nlohmann::json spec = {{"type", "svr_hyperparameters"}, {"data", (dir.path() / "train.csv").string()},
                                 {"lags", {{"m", 2}, {"n", 2}}}, {"fitness", fitness}};
    const auto problem = make_problem(spec, dir.path());
    ASSERT_EQ(problem->dimension(), 3);
    Eigen::MatrixXd X(3, 2);
    X << -3, -2, 2, 1, 0, -0.5;
    Eigen::VectorXd f1(2), f2(2);
    problem->evaluate(X, f1);
    problem->evaluate(X, f2);
    EXPECT_TRUE(std::isfinite(f1[0]) && std::isfinite(f1[1])) << fitness;
    EXPECT_EQ(f1[0], f2[0]) << fitness;
    EXPECT_EQ(f1[1], f2[1]) << fitness;
  }
}

TEST(SvrHyperparameters, BadSpecIsNamed) {
  try {
    make_problem({{"type", "svr_hyperparameters"}, {"data", "x.csv"}, {"fitnes", "cv"}}, ".");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fitnes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hystbench

namespace hystbench {
namespace {

// `hystbench run` tunes the hyperparameters with any optimizer; the same
// seed gives the same tuned values on 1 and 2 threads.
TEST(SvrHyperparameters, TunedBySwarmTheSameOnOneAndTwoThreads) {
  test_support::TempDir dir;
  write_loop_record(dir.path() / "train.csv", 300);
  const nlohmann::json experiment = {
      {"name", "svr_tuning"},
      // A narrow C range: libsvm's large-C solves are the slow ones.
      {"problem",
       {{"type", "svr_hyperparameters"}, {"data", "train.csv"}, {"lags", {{"m", 2}, {"n", 2}}},
        {"log10_C", {-1, 2}}}},
      {"budget", {{"evaluations", 12}}},
      {"trials", 2},
      {"seed", 3},
      {"algorithms", {{{"name", "pso"}, {"label", "PSO"}, {"params", {{"swarm", 6}}}}}}};
  std::ofstream(dir.path() / "svr.json") << experiment.dump();
  std::vector<nlohmann::json> best;
  for (const char* threads : {"1", "2"}) {
    const auto out = dir.path() / (std::string("out") + threads);
    const auto r = test_support::hystbench("run " + (dir.path() / "svr.json").string() + " --out " +
                                           out.string() + " --threads " + threads);
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(out / "summary.json");
    best.push_back(nlohmann::json::parse(in)["algorithms"][0]["best_x"]);
  }
  EXPECT_EQ(best[0], best[1]);
  EXPECT_TRUE(best[0].contains("log10_sigma")) << best[0];
}

}  // namespace
}  // namespace hystbench
