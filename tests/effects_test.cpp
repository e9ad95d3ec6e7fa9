// Physical effect plugins (problems/hammerstein/effects): hand-computed
// outputs, and contracts every registered effect must keep (exact neutral,
// bounds, units, scale invariance, failure as false).
#include <gtest/gtest.h>

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/io/measurement.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/model.hpp"
#include "framework/model/model_data.hpp"
#include "problems/hammerstein/batched_sse.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"
#include "tests/active_point.hpp"

namespace hystbench {
namespace {

// Normalised data with unit scales: t = k·Ts.
ModelData data_of(const std::vector<double>& u, double Ts = 0.01) {
  ModelData d;
  const auto n = Eigen::Index(u.size());
  d.u = Eigen::Map<const Eigen::VectorXd>(u.data(), n);
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, Ts * double(n - 1));
  d.y = Eigen::VectorXd::Zero(n);
  d.sample_time = Ts;
  d.estimation = Eigen::VectorXd::Ones(n);
  return d;
}

Eigen::VectorXd params(std::initializer_list<double> x) {
  Eigen::VectorXd v(Eigen::Index(x.size()));
  Eigen::Index i = 0;
  for (double e : x) v[i++] = e;
  return v;
}

Eigen::VectorXd run(const std::string& model, std::initializer_list<double> x,
                    const std::vector<double>& u, double Ts = 0.01) {
  const Model m = Model::parse(model);
  Eigen::VectorXd y;
  EXPECT_TRUE(m.simulate(params(x), data_of(u, Ts), y)) << model;
  return y;
}

void expect_values(const Eigen::VectorXd& y, const std::vector<double>& expected,
                   double tol = 1e-12) {
  ASSERT_EQ(y.size(), Eigen::Index(expected.size()));
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(y[Eigen::Index(k)], expected[k], tol) << "sample " << k;
}

// A record with steps, sweeps and reversals: 2 s at 1 kHz.
Measurement test_record(double u_scale = 1.0, double y_scale = 1.0) {
  Measurement m;
  const int n = 2000;
  m.sample_time = 1e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * (n - 1));
  m.u.resize(n);
  for (int k = 0; k < n; ++k) {
    const double t = m.t[k];
    const double chirp = 0.8 * std::sin(2 * std::numbers::pi * (3.0 + 20.0 * t) * t);
    const double fast = 0.3 * std::sin(2 * std::numbers::pi * 47.0 * t);
    m.u[k] = u_scale * (chirp + (t > 1.0 ? 0.5 : 0.0) + fast);
  }
  m.y = y_scale * m.u;
  return m;
}

// ---------------------------------------------------------------- outputs

TEST(EffectHysteresis, MatchesHandComputedBoucWenIncrements) {
  // A = 0.5, β = 1, γ = 0.5, v = 0.2, 0.5, 0.3, −0.1 from rest:
  // h = 0.1; 0.1 + 0.15 − 0.03 − 0.015 = 0.205; 0.205 − 0.1 − 0.041 + 0.0205 = 0.0845;
  // 0.0845 − 0.2 − 0.0338 + 0.0169 = −0.1324. Output gain·v − h with gain 2.
  const auto y = run("hysteresis", {2.0, 0.5, 1.0, 0.5}, {0.2, 0.5, 0.3, -0.1});
  expect_values(y, {0.4 - 0.1, 1.0 - 0.205, 0.6 - 0.0845, -0.2 + 0.1324});
}

TEST(EffectAsymmetry, AddsQuadraticOfTheDrive) {
  // gain·v + d2·v² with gain 2, d2 = 0.5: the square is of v, not of gain·v.
  const auto y = run("asymmetry", {2.0, 0.5}, {1.0, -2.0, 0.5});
  expect_values(y, {2.5, -2.0, 1.125});
}

TEST(EffectSaturation, LimitsByTheAlgebraicSigmoidAtTheNeutralSoftness) {
  // λ = 1/L² = 0.25, softness 1/p = 0.5: L = 2, y = u/√(1 + u²/4).
  const auto y = run("saturation", {1.0, 0.25, 0.5}, {1.0, -2.0, 4.0});
  expect_values(y, {1.0 / std::sqrt(1.25), -2.0 / std::sqrt(2.0), 4.0 / std::sqrt(5.0)});
}

TEST(EffectSaturation, SoftnessSpansAHardClipToTheSoftestBend) {
  // L = 2. Softness 0 (p = ∞): a clip at ±2. Softness 1 (p = 1): u/(1 + |u|/2).
  // Softness 0.25 (p = 4): u/(1 + (u/2)⁴)^(1/4); beyond the knee it is computed
  // from 2/u, so a huge drive gives the limit, not 0 from an overflow.
  expect_values(run("saturation", {1.0, 0.25, 0.0}, {1.0, -2.0, 4.0, 1e200}), {1.0, -2.0, 2.0, 2.0});
  expect_values(run("saturation", {1.0, 0.25, 1.0}, {1.0, -2.0, 4.0}), {2.0 / 3.0, -1.0, 4.0 / 3.0});
  expect_values(run("saturation", {1.0, 0.25, 0.25}, {1.0, -4.0, 1e200}),
                {1.0 / std::pow(1.0 + 1.0 / 16.0, 0.25), -4.0 / std::pow(17.0, 0.25), 2.0});
}

TEST(EffectSaturation, ANanStaysANanWhateverTheShape) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double softness : {0.0, 0.4, 1.0}) {
    const Model m = Model::parse("saturation");
    Eigen::VectorXd y;
    m.simulate(params({1.0, 0.25, softness}), data_of({1.0, nan}, 0.01), y);
    ASSERT_EQ(y.size(), 2);
    EXPECT_TRUE(std::isnan(y[1])) << "softness " << softness;
  }
}

TEST(EffectSaturation, WithoutALimitTheSignalPassesWhateverTheShape) {
  expect_values(run("saturation", {1.0, 0.0, 0.0}, {1.0, -3.0}), {1.0, -3.0});
}

TEST(EffectSaturation, SaturatesTheStaticPartListedBeforeIt) {
  // u = 1: gain·v + d2·v² = 1.5, then 1.5/√(1 + 1.5²/4).
  const auto y = run("asymmetry,saturation", {1.0, 0.5, 0.25, 0.5}, {1.0});
  expect_values(y, {1.5 / std::sqrt(1.0 + 2.25 / 4.0)});
}

TEST(EffectBacklash, PlayOperatorFromRest) {
  // r = 0.5, F[-1] = 0: 0, 0.5, 0.7, hold 0.7 through the reversal, then −0.5.
  const auto y = run("backlash", {2.0, 0.5}, {0.2, 1.0, 1.2, 0.9, 0.4, 0.8, -1.0});
  expect_values(y, {0.0, 1.0, 1.4, 1.4, 1.4, 1.4, -1.0});
}

TEST(EffectDelay, IntegerDelayShiftsInZeros) {
  const auto y = run("delay", {1.0, 2.0}, {1, 2, 3, 4, 5});
  expect_values(y, {0, 0, 1, 2, 3}, 0.0);
}

TEST(EffectDelay, FractionalDelayIsCatmullRomInterpolation) {
  // d = 1.5: halfway weights −1/16, 9/16, 9/16, −1/16 on v[k−3], v[k−2], v[k−1], v[k].
  const auto y = run("delay", {1.0, 1.5}, {1, 2, 4, 8, 16});
  expect_values(y, {-0.0625, 0.4375, 1.4375, 2.8125, 5.625});
}

TEST(EffectDelay, RampIsDelayedExactlyForAnyFraction) {
  std::vector<double> ramp(12);
  for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = double(k);
  for (double d : {0.25, 0.5, 1.0, 1.75, 3.4}) {
    const auto y = run("delay", {1.0, d}, ramp);
    for (Eigen::Index k = Eigen::Index(std::floor(d)) + 2; k < y.size(); ++k)
      EXPECT_NEAR(y[k], double(k) - d, 1e-12) << "d = " << d << ", k = " << k;
  }
}

TEST(EffectDelay, IsSmoothInTheDelay) {
  // Crossing an integer delay changes the output continuously and with a
  // continuous slope (no kink for the optimizer).
  std::vector<double> u(50);
  for (std::size_t k = 0; k < u.size(); ++k)
    u[k] = std::sin(0.4 * double(k)) + 0.01 * double(k * k);
  const double h = 1e-5;
  for (double d : {1.0, 2.0}) {
    const auto below = run("delay", {1.0, d - h}, u), at = run("delay", {1.0, d}, u),
               above = run("delay", {1.0, d + h}, u);
    const double left = (at - below).norm() / h, right = (above - at).norm() / h;
    EXPECT_GT(left, 0.1);
    EXPECT_NEAR(left, right, 1e-3 * left) << "slope jumps at d = " << d;
  }
}

TEST(EffectMsd, MatchesTrapezoidalIntegrationOfTheOscillator) {
  // Reference: the ODE κ²ÿ + 2ζκẏ + y = w (κ = 0.05 s / 2π, ζ = 0.3) integrated
  // with the trapezoidal rule in state-space form, which the bilinear
  // transform equals; Ts = 0.01 s.
  const auto y = run("msd", {1.0, 0.05, 0.3}, {1, 1, 1, 0, 0, -0.5});
  expect_values(y, {0.2228184224460015, 0.820679125017808, 1.323943083369065, 1.1015017685321633,
                    0.21479964144791439, -0.5974192440284525});
}

TEST(EffectMsd, UnitStaticGain) {
  const auto y = run("msd", {1.5, 0.05, 0.3}, std::vector<double>(3000, 2.0));
  EXPECT_NEAR(y[y.size() - 1], 3.0, 1e-9);
}

TEST(EffectMsd, TinyPeriodIsCloseToPassThrough) {
  const Measurement m = test_record();
  const ModelData d(m, SignalScales{});
  const Model model = Model::parse("msd");
  Eigen::VectorXd y;
  ASSERT_TRUE(model.simulate(params({1.0, 1e-9, 0.5}), d, y));
  EXPECT_LT((y - d.u).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_GT((y - d.u).cwiseAbs().maxCoeff(), 0.0);
}

TEST(EffectArx, MatchesHandComputedRecursion) {
  // a1 = −0.5, a2 = 0.2, b1 = 0.3, b2 = 0.1 → b0 = 1 − 0.5 + 0.2 − 0.4 = 0.3.
  // y0 = 0.3; y1 = 0.3 + 0.15 = 0.45; y2 = 0.1 + 0.225 − 0.06 = 0.265;
  // y3 = 0.6 + 0.1325 − 0.09 = 0.6425.
  const auto y = run("arx", {1.0, -0.5, 0.2, 0.3, 0.1}, {1, 0, 0, 2});
  expect_values(y, {0.3, 0.45, 0.265, 0.6425});
}

TEST(EffectArx, UnitStaticGain) {
  const auto y = run("arx", {1.0, -1.2, 0.4, 0.5, -0.3}, std::vector<double>(2000, 1.0));
  EXPECT_NEAR(y[y.size() - 1], 1.0, 1e-9);
}

TEST(EffectCreep, StepResponseIsTheSumOfFourLags) {
  // Ts = 0.1 s, γ = 0.1, unit step: y[k] = 1 + 0.1·Σ_τ (1 − exp(−(k+1)·0.1/τ)).
  const auto y = run("creep", {1.0, 0.1}, {1, 1, 1, 1}, 0.1);
  expect_values(y, {1.0738232807210055, 1.1067733291711317, 1.1241944681898537,
                    1.1354566886579311});
}

TEST(EffectCreep, GrowsAboutGammaPerDecadeOfTime) {
  // After a unit step the creep term rises by about γ per decade between 1 s and 100 s.
  const double gamma = 0.05;
  const auto y = run("creep", {1.0, gamma}, std::vector<double>(100000, 1.0), 1e-3);
  const double at1 = y[999], at10 = y[9999], at100 = y[99999];
  EXPECT_NEAR((at10 - at1) / gamma, 1.0, 0.15);
  EXPECT_NEAR((at100 - at10) / gamma, 1.0, 0.15);
}

TEST(EffectDrift, AddsRateTimesTime) {
  const auto y = run("drift", {1.0, 0.2}, {1, 1, 1}, 0.5);
  expect_values(y, {1.0, 1.1, 1.2});
}

TEST(EffectSecondMode, SharesTheOutputWithAParallelResonance) {
  // g = 0.5, f = 10 Hz (log10 f = 1), ζ = 0.2, Ts = 0.01 s, no other
  // dynamics: y = 0.5·w + 0.5·H2·w, H2 integrated with the trapezoidal rule.
  const auto y = run("second_mode", {1.0, 0.5, 1.0, 0.2}, {1, 1, 1, 0, 0, -0.5});
  expect_values(y, {0.5403051652091799, 0.6802562324416089, 0.8945777943221693,
                    0.5585923390558124, 0.549131117870556, 0.0943968793851116});
}

TEST(EffectSecondMode, MixesWithTheFirstModeByParticipation) {
  const Measurement m = test_record();
  const ModelData d(m, SignalScales{});
  Eigen::VectorXd first, second, both;
  ASSERT_TRUE(Model::parse("msd").simulate(params({1.3, 0.03, 0.2}), d, first));
  ASSERT_TRUE(Model::parse("second_mode").simulate(params({1.3, 1.0, 2.2, 0.05}), d, second));
  ASSERT_TRUE(Model::parse("msd,second_mode")
                  .simulate(params({1.3, 0.03, 0.2, 0.3, 2.2, 0.05}), d, both));
  EXPECT_LT((both - (0.7 * first + 0.3 * second)).cwiseAbs().maxCoeff(), 1e-12);
}

// The seed's 13 parameters mapped onto gain + hysteresis, asymmetry, msd,
// arx: the chain's blocks have unit static gain, so the seed's static gains
// 1/K (MSD) and (a + b)/(1 + c + d) (ARX) move into gain, A and d2.
Eigen::VectorXd chain_parameters(const HammersteinParams& s) {
  const double arx_gain = (s.a + s.b) / (1.0 + s.c + s.d);
  const double g = arx_gain / s.K;
  const double omega = std::sqrt(s.K / s.M), zeta = s.D / (2.0 * std::sqrt(s.K * s.M));
  return params({s.d1 * g, s.alpha * s.L * g, s.beta, s.gamma, s.d2 * g,
                 2.0 * std::numbers::pi / omega, zeta, s.c, s.d, s.a / arx_gain, s.b / arx_gain});
}

const HammersteinParams kSeedExample{0.4, 0.0015, 0.0005, 0.2, 0.15, 6e-5, 1.583e-5,
                                     0.001194, 1.0, 0.2, 0.09, -1.0, 0.29};

TEST(EffectChain, ReproducesTheSeedHammersteinModel) {
  const double Ts = 1e-3;
  const Measurement m = test_record(600.0);
  const Eigen::VectorXd seed = simulate_hammerstein(kSeedExample, m.u, Ts, BoucWenForm::Increment);
  ModelData d(m, SignalScales{});
  Eigen::VectorXd y;
  ASSERT_TRUE(Model::parse("hysteresis,asymmetry,msd,arx").simulate(chain_parameters(kSeedExample), d, y));
  EXPECT_LT((y - seed).norm(), 1e-10 * seed.norm());
}

// The 13-parameter problem keeps its own batched kernel for speed; it must
// score every candidate as the effect chain does (increment form).
TEST(EffectChain, TheSeedProblemsBatchedKernelScoresAsTheChain) {
  const double Ts = 1e-3;
  Measurement m = test_record(600.0);
  m.y = simulate_hammerstein(kSeedExample, m.u, Ts, BoucWenForm::Increment);
  for (Eigen::Index k = 0; k < m.y.size(); ++k) m.y[k] += 0.5 * std::sin(0.37 * double(k));
  std::vector<HammersteinParams> candidates(11, kSeedExample);
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    HammersteinParams& c = candidates[i];
    c.beta *= 1.0 + 0.1 * double(i);
    c.d2 *= 1.0 - 0.05 * double(i);
    c.D *= 1.0 + 0.2 * double(i);
    c.a *= 1.0 + 0.01 * double(i);
  }
  Eigen::MatrixXd X(HammersteinParams::kCount, Eigen::Index(candidates.size()));
  for (std::size_t i = 0; i < candidates.size(); ++i) X.col(Eigen::Index(i)) = candidates[i].to_vector();
  Eigen::VectorXd batched(X.cols());
  hammerstein_sse_batched(X, m.u, m.y, Ts, BoucWenForm::Increment, batched);
  const Model model = Model::parse("hysteresis,asymmetry,msd,arx");
  const ModelData d(m, SignalScales{});
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    Eigen::VectorXd y;
    ASSERT_TRUE(model.simulate(chain_parameters(candidates[i]), d, y)) << "candidate " << i;
    const double chain = (m.y - y).squaredNorm();
    EXPECT_NEAR(batched[Eigen::Index(i)], chain, 1e-9 * chain) << "candidate " << i;
  }
}

// Columns of the finite-difference Jacobian of the model output, each
// normalised to unit length.
Eigen::MatrixXd normalised_jacobian(const Model& model, const Eigen::VectorXd& x,
                                    const ModelData& d) {
  Eigen::MatrixXd J(d.size(), model.dimension());
  for (int i = 0; i < model.dimension(); ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
    Eigen::VectorXd up = x, down = x, y_up, y_down;
    up[i] += h;
    down[i] -= h;
    EXPECT_TRUE(model.simulate(up, d, y_up) && model.simulate(down, d, y_down));
    J.col(i) = (y_up - y_down).normalized();
  }
  return J;
}

// A 30 s record at 200 Hz: a staircase (a level every 3 s) under a
// 0.5-40 Hz sweep, so that slow and fast effects both show.
Measurement staircase_record() {
  Measurement m;
  const int n = 6000;
  m.sample_time = 5e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 5e-3 * (n - 1));
  m.u.resize(n);
  const double levels[] = {0.0, 1.0, 0.4, 1.6, -0.5, 0.8, 2.0, 0.2, 1.2, -0.2};
  for (int k = 0; k < n; ++k) {
    const double t = m.t[k];
    const double sweep = 0.5 * std::sin(2 * std::numbers::pi * (0.5 + 0.65 * t) * t);
    m.u[k] = levels[int(t / 3.0) % 10] + sweep;
  }
  m.y = m.u;
  return m;
}

TEST(EffectCatalog, NoFlatDirectionAgainstTheGainOrWithinTheChain) {
  // Smallest singular value of the normalised Jacobian: 0 would mean a
  // direction of parameters that leaves the output unchanged.
  const ModelData d(staircase_record(), SignalScales{});
  const std::vector<std::pair<std::string, Eigen::VectorXd>> cases = {
      {"hysteresis", params({1.3, 0.6, 0.9, 0.3})},
      {"asymmetry", params({1.3, 0.2})},
      {"saturation", params({1.3, 0.3, 0.4})},
      {"backlash", params({1.3, 0.1})},
      {"delay", params({1.3, 2.5})},
      {"msd", params({1.3, 0.1, 0.2})},
      {"arx", params({1.3, -1.2, 0.5, 0.2, 0.1})},
      {"second_mode", params({1.3, 0.2, 1.3, 0.05})},
      {"creep", params({1.3, 0.03})},
      {"drift", params({1.3, 0.01})},
      {"offset", params({1.3, 0.1})},
      {"hysteresis,asymmetry,msd,arx",
       params({1.3, 0.6, 0.9, 0.3, 0.2, 0.1, 0.2, -1.2, 0.5, 0.2, 0.1})},
      {"delay,hysteresis,asymmetry,saturation,msd,second_mode,creep,drift,offset",
       params({1.3, 2.5, 0.6, 0.9, 0.3, 0.2, 0.3, 0.4, 0.1, 0.2, 0.2, 1.3, 0.05, 0.03, 0.01, 0.1})},
  };
  for (const auto& [name, x] : cases) {
    SCOPED_TRACE(name);
    const Model model = Model::parse(name);
    ASSERT_EQ(model.dimension(), x.size());
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(normalised_jacobian(model, x, d));
    const auto& sv = svd.singularValues();
    EXPECT_GT(sv[sv.size() - 1], 1e-3) << "singular values " << sv.transpose();
  }
}

TEST(EffectCreep, SeparatesFromTheGainOnAStaircase) {
  // Simulated 30 s staircase with creep: a scan of gamma at the true gain
  // has its minimum at the true value, and the gain column of the Jacobian
  // is far from parallel to the creep column.
  const ModelData d(staircase_record(), SignalScales{});
  const Model model = Model::parse("creep");
  Eigen::VectorXd truth;
  ASSERT_TRUE(model.simulate(params({1.0, 0.04}), d, truth));
  const Eigen::MatrixXd J = normalised_jacobian(model, params({1.0, 0.04}), d);
  EXPECT_LT(std::abs(J.col(0).dot(J.col(1))), 0.99);
  double best = 0.0, best_sse = std::numeric_limits<double>::infinity();
  for (double gamma = 0.0; gamma <= 0.1; gamma += 0.005) {
    Eigen::VectorXd y;
    ASSERT_TRUE(model.simulate(params({1.0, gamma}), d, y));
    const double sse = (y - truth).squaredNorm();
    if (sse < best_sse) best_sse = sse, best = gamma;
  }
  EXPECT_NEAR(best, 0.04, 1e-9);
}

// ------------------------------------------------- registry-wide contracts

std::vector<std::string> all_effects() {
  std::vector<std::string> names;
  for (const auto* info : EffectRegistry::instance().all()) names.push_back(info->name);
  return names;
}

TEST(EffectCatalog, HasTheDesignedEffects) {
  const auto names = all_effects();
  for (const char* n : {"hysteresis", "asymmetry", "saturation", "backlash", "delay", "msd", "arx",
                        "creep", "offset", "drift", "second_mode"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

// An empty list is refused rather than read as the gain alone, which has to
// be asked for by name.
TEST(EffectCatalog, EmptyModelListIsRefusedAndNoneIsTheGainAlone) {
  for (const char* list : {"", " ", " , "}) {
    try {
      Model::parse(list, "--start");
      ADD_FAILURE() << "'" << list << "' was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--start: the effect list is empty; write none for the gain alone, or effects such "
                "as hysteresis,msd (`hystbench list effects` lists them)");
    }
  }
  const Model gain = Model::parse("none");
  EXPECT_TRUE(gain.effects().empty());
  EXPECT_EQ(gain.parameter_names(), std::vector<std::string>{"gain"});
  EXPECT_EQ(gain.text(), "none");
}

TEST(EffectCatalog, NeutralIsInsideBoundsAndEveryFieldIsDocumented) {
  for (const auto* info : EffectRegistry::instance().all()) {
    SCOPED_TRACE(info->name);
    EXPECT_FALSE(info->summary.empty());
    EXPECT_FALSE(info->citation.empty());
    EXPECT_FALSE(info->signature.empty());
    EXPECT_FALSE(info->statistic.name.empty());
    EXPECT_TRUE(info->statistic.compute);
    EXPECT_NE(info->statistic.sentence.find("{value}"), std::string::npos);
    EXPECT_FALSE(info->params.empty());
    for (const auto& p : info->params) {
      SCOPED_TRACE(p.name);
      EXPECT_FALSE(p.name.empty());
      EXPECT_FALSE(p.doc.empty());
      EXPECT_LT(p.lower, p.upper);
      EXPECT_LE(p.lower, p.neutral);
      EXPECT_LE(p.neutral, p.upper);
    }
  }
}

TEST(EffectCatalog, NeutralIsAnExactPassThrough) {
  const Measurement m = test_record();
  const ModelData d(m, SignalScales{});
  for (const auto& name : all_effects()) {
    SCOPED_TRACE(name);
    const Model model = Model::parse(name);
    Eigen::VectorXd x = model.neutral();
    x[0] = 1.7;
    Eigen::VectorXd y;
    ASSERT_TRUE(model.simulate(x, d, y));
    const Eigen::VectorXd expected = 1.7 * d.u;
    for (Eigen::Index k = 0; k < y.size(); ++k) ASSERT_EQ(y[k], expected[k]) << "sample " << k;
  }
}

TEST(EffectCatalog, AddingANeutralEffectKeepsTheFittedOutputExactly) {
  // Discovery warm-starts an extended model where the current fit is.
  const Measurement m = test_record();
  const ModelData d(m, SignalScales{});
  for (const auto& name : all_effects()) {
    SCOPED_TRACE(name);
    const auto& info = EffectRegistry::instance().find(name, "effect");
    Model base = Model::parse("backlash,hysteresis,asymmetry,msd,creep");
    for (const auto& drop : {name, info.extends})
      if (base.has(drop)) base = base.without(drop);
    Eigen::VectorXd x = base.neutral();
    const std::vector<std::pair<std::string, double>> fit = {
        {"gain", 1.3},        {"backlash.r", 0.05}, {"hysteresis.A", 0.6}, {"hysteresis.beta", 0.9},
        {"hysteresis.gamma", 0.3}, {"asymmetry.d2", 0.2}, {"msd.period", 0.02}, {"msd.zeta", 0.15},
        {"creep.gamma", 0.03}};
    const auto names = base.parameter_names();
    for (const auto& [key, value] : fit) {
      const auto it = std::find(names.begin(), names.end(), key);
      if (it != names.end()) x[it - names.begin()] = value;
    }
    const Model extended = base.with(name);
    const Eigen::VectorXd x_ext = extended.carry_over(base, x);
    Eigen::VectorXd y_base, y_ext;
    ASSERT_TRUE(base.simulate(x, d, y_base));
    ASSERT_TRUE(extended.simulate(x_ext, d, y_ext));
    for (Eigen::Index k = 0; k < y_base.size(); ++k)
      ASSERT_EQ(y_ext[k], y_base[k]) << "sample " << k;
  }
}

using test_support::active_point;

TEST(EffectCatalog, PhysicalOutputDoesNotDependOnTheNormalisation) {
  // The same physical parameters simulated under two different signal
  // scales must predict the same physical output: this checks every
  // parameter's declared y_power and u_power.
  const Measurement m = test_record(37.0, 0.02);
  const SignalScales s1 = SignalScales::of(m), s2{s1.u * 3.1, s1.y * 0.23};
  const ModelData d1(m, s1), d2(m, s2);
  for (const auto& name : all_effects()) {
    SCOPED_TRACE(name);
    const Model model = Model::parse(name);
    Eigen::VectorXd x1, y1, y2;
    bool ok = false;
    for (double step : {0.25, 0.1, 0.03}) {
      x1 = active_point(model, step);
      if ((ok = model.simulate(x1, d1, y1))) break;
    }
    ASSERT_TRUE(ok) << "no stable point found near neutral";
    const auto physical = model.physical_values(x1, s1);
    const Eigen::VectorXd x2 = model.from_physical(physical, s2, "test");
    ASSERT_TRUE(model.simulate(x2, d2, y2));
    const Eigen::VectorXd p1 = y1 * s1.y, p2 = y2 * s2.y;
    EXPECT_GT((p1 - m.u * (1.3 * s1.y / s1.u)).norm(), 1e-6 * p1.norm()) << "effect inactive";
    EXPECT_LT((p1 - p2).norm(), 1e-9 * p1.norm());
  }
}

TEST(EffectCatalog, PhysicalValuesRoundTrip) {
  const Model model = Model::parse(
      "backlash,delay,hysteresis,asymmetry,saturation,msd,arx,second_mode,creep,drift,offset");
  const SignalScales scales{412.0, 3.5e-5};
  Eigen::VectorXd x = active_point(model, 0.37);
  const auto values = model.physical_values(x, scales);
  const Eigen::VectorXd back = model.from_physical(values, scales, "test");
  for (int i = 0; i < model.dimension(); ++i) EXPECT_NEAR(back[i], x[i], 1e-12 * std::abs(x[i]));
  // Spot checks of the conversion itself.
  const auto names = model.parameter_names();
  auto value_of = [&](const std::string& key) {
    return x[std::find(names.begin(), names.end(), key) - names.begin()];
  };
  EXPECT_DOUBLE_EQ(values["hysteresis.A"].get<double>(), value_of("hysteresis.A") * 3.5e-5 / 412.0);
  EXPECT_DOUBLE_EQ(values["asymmetry.d2"].get<double>(),
                   value_of("asymmetry.d2") * 3.5e-5 / (412.0 * 412.0));
  EXPECT_DOUBLE_EQ(values["saturation.lambda"].get<double>(),
                   value_of("saturation.lambda") / (3.5e-5 * 3.5e-5));
  EXPECT_DOUBLE_EQ(values["drift.c1"].get<double>(), value_of("drift.c1") * 3.5e-5);
  EXPECT_DOUBLE_EQ(values["msd.period"].get<double>(), value_of("msd.period"));
}

TEST(EffectCatalog, UnitsReadAsPhysicalUnits) {
  const Model model = Model::parse(
      "backlash,delay,hysteresis,asymmetry,saturation,msd,arx,second_mode,creep,drift");
  const auto units = model.physical_units("V", "µm");
  EXPECT_EQ(units["gain"], "µm/V");
  EXPECT_EQ(units["hysteresis.A"], "µm/V");
  EXPECT_EQ(units["hysteresis.beta"], "1/V");
  EXPECT_EQ(units["hysteresis.gamma"], "1/V");
  EXPECT_EQ(units["asymmetry.d2"], "µm/V^2");
  EXPECT_EQ(units["saturation.lambda"], "1/µm^2");
  EXPECT_EQ(units["backlash.r"], "V");
  EXPECT_EQ(units["delay.d"], "samples");
  EXPECT_EQ(units["msd.period"], "s");
  EXPECT_EQ(units["msd.zeta"], "");
  EXPECT_EQ(units["second_mode.log10_f"], "log10(Hz)");
  EXPECT_EQ(units["creep.gamma"], "");
  EXPECT_EQ(units["drift.c1"], "µm/s");
}

TEST(EffectCatalog, UnstableParametersGiveFalseNotNan) {
  // A violent alternating drive: β·|Δv| = 60 makes the Bouc-Wen loop explode.
  std::vector<double> u(400);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = k % 2 ? 3.0 : -3.0;
  const ModelData d = data_of(u, 1e-3);
  const std::vector<std::pair<std::string, Eigen::VectorXd>> cases = {
      {"msd", params({1.0, 0.02, -0.1})},
      {"arx", params({1.0, -0.5, 1.2, 0.0, 0.0})},
      {"arx", params({1.0, 2.1, 0.5, 0.0, 0.0})},
      {"second_mode", params({1.0, 0.2, 2.0, -0.05})},
      {"backlash", params({1.0, -0.1})},
      {"delay", params({1.0, -1.0})},
      {"saturation", params({1.0, -0.5, 0.5})},
      {"saturation", params({1.0, 0.5, 1.5})},
      {"hysteresis", params({1.0, 10.0, 10.0, -10.0})},
      // tanh would turn the diverged loop into finite numbers: the hysteresis
      // itself must report the failure.
      {"hysteresis,saturation", params({1.0, 10.0, 10.0, -10.0, 1.0, 0.5})},
      {"creep", params({1.0, std::numeric_limits<double>::quiet_NaN()})},
  };
  for (const auto& [model, x] : cases) {
    SCOPED_TRACE(model);
    Eigen::VectorXd y;
    EXPECT_FALSE(Model::parse(model).simulate(x, d, y));
  }
}

TEST(EffectCatalog, CatalogEffectsAreCausal) {
  // Changing the input after sample k0 leaves every output up to k0 alone
  // (the fractional delay must not peek at the next sample).
  const Measurement m = test_record();
  ModelData d(m, SignalScales{});
  ModelData later = d;
  const Eigen::Index k0 = 700;
  later.u.tail(d.size() - k0 - 1).array() += 0.5;
  for (const char* name : {"hysteresis", "asymmetry", "saturation", "backlash", "delay", "msd",
                           "arx", "creep", "drift", "second_mode", "offset"}) {
    SCOPED_TRACE(name);
    const Model model = Model::parse(name);
    for (double step : {0.03, 0.2}) {
      const Eigen::VectorXd x = active_point(model, step);
      Eigen::VectorXd y, y_later;
      ASSERT_TRUE(model.simulate(x, d, y));
      ASSERT_TRUE(model.simulate(x, later, y_later));
      EXPECT_EQ(y.head(k0 + 1), y_later.head(k0 + 1)) << "step " << step;
      EXPECT_NE(y.tail(d.size() - k0 - 1), y_later.tail(d.size() - k0 - 1)) << "step " << step;
    }
  }
}

TEST(EffectCatalog, SimulatesConcurrentlyWithTheSameResult) {
  // apply is const and keeps no state: several threads share one model.
  const Measurement m = test_record();
  const ModelData d(m, SignalScales{});
  const Model model = Model::parse(
      "backlash,delay,hysteresis,asymmetry,saturation,msd,arx,second_mode,creep,drift,offset");
  const Eigen::VectorXd x = active_point(model, 0.2);
  Eigen::VectorXd serial;
  ASSERT_TRUE(model.simulate(x, d, serial));
  std::vector<Eigen::VectorXd> out(4);
  std::vector<int> ok(4, 0);
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([&, i] {
      for (int r = 0; r < 20; ++r) ok[i] = model.simulate(x, d, out[i]) ? 1 : 0;
    });
  for (auto& t : threads) t.join();
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(ok[i], 1);
    EXPECT_EQ(out[i], serial);
  }
}

}  // namespace
}  // namespace hystbench
