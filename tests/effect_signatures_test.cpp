// Each catalog effect's own residual statistic (EffectInfo::statistic), on
// residuals built by hand with a known answer, and how the framework collects
// them: every registered effect, in metrics.json, in report.md and in the
// evidence of a diagnosis candidate.
#include "framework/discovery/effect_signatures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>

#include "framework/core/rng.hpp"
#include "framework/discovery/comparison.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/evidence.hpp"
#include "framework/discovery/excitation_frequency.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTs = 0.001;
constexpr Eigen::Index kN = 4000;

Eigen::VectorXd times() { return Eigen::VectorXd::LinSpaced(kN, 0.0, double(kN - 1) * kTs); }

Eigen::VectorXd sine(double f, double phase = 0.0) {
  return (2 * kPi * f * times().array() + phase).sin().matrix();
}

Eigen::VectorXd gaussian(double sigma, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::VectorXd out(kN);
  for (Eigen::Index i = 0; i < kN; ++i) out[i] = sigma * rng.normal();
  return out;
}

// A triangle wave between −1 and 1 with period `period` samples, starting at
// the top and falling, shifted by `shift` samples.
Eigen::VectorXd triangle(Eigen::Index period, Eigen::Index shift = 0) {
  Eigen::VectorXd out(kN);
  for (Eigen::Index k = 0; k < kN; ++k) {
    const double phase = double((k + shift) % period) / double(period);  // 0..1
    out[k] = phase < 0.5 ? 1.0 - 4.0 * phase : -3.0 + 4.0 * phase;
  }
  return out;
}

// The stop operator of a triangle wave between −1 and 1, by hand: after a
// reversal at the top the output falls from +r with the input until it
// reaches −r and stays there; after one at the bottom it rises from −r to +r.
Eigen::VectorXd triangle_loop(const Eigen::VectorXd& x, double r) {
  Eigen::VectorXd out(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const bool falling = k + 1 < x.size() ? x[k + 1] < x[k] : x[k] < x[k - 1];
    out[k] = falling ? std::max(-r, r - (1.0 - x[k])) : std::min(r, -r + (x[k] + 1.0));
  }
  return out;
}

// A record owning what a ResidualView points at.
struct Record {
  Eigen::VectorXd t, u, y_model, e;
  std::vector<std::string> segment;
  Correlation ccf;
  double f_low;

  Record(Eigen::VectorXd u_, Eigen::VectorXd y_model_, Eigen::VectorXd e_)
      : t(times()),
        u(std::move(u_)),
        y_model(std::move(y_model_)),
        e(std::move(e_)),
        ccf(cross_correlation(u, e, kCorrelationLags)),
        f_low(lowest_excitation_frequency(u, segment, kTs)) {}
  ResidualView view() const { return {t, u, y_model, e, segment, kTs, ccf, f_low}; }
};

SignatureValue statistic(const std::string& effect, const Record& r) {
  const auto& info = EffectRegistry::instance().find(effect, "effect");
  return info.statistic.compute(r.view());
}

double detail(const SignatureValue& v, const std::string& name) {
  for (const auto& [key, x] : v.details)
    if (key == name) return x;
  ADD_FAILURE() << "no detail " << name;
  return std::nan("");
}

// ---- the statistic of each catalog effect on its own residual ----------------------

TEST(EffectSignatures, OffsetIsTheMeanInStandardDeviations) {
  // e = 0.3 + N(0, 0.1²): mean / std = 3.
  const Record r(sine(2), sine(2), (0.3 + gaussian(0.1, 1).array()).matrix());
  EXPECT_NEAR(statistic("offset", r).value, 3.0, 0.15);
}

TEST(EffectSignatures, DriftIsTheCorrelationWithTime) {
  // e = 0.5 t + N(0, 0.3²) over T = 4 s: var(0.5 t) = 0.25 T²/12 = 1/3, so
  // r = √(1/3) / √(1/3 + 0.09) = 0.887.
  const Record r(sine(2), sine(2), 0.5 * times() + gaussian(0.3, 2));
  EXPECT_NEAR(statistic("drift", r).value, 0.887, 0.02);
}

TEST(EffectSignatures, AsymmetryIsTheCorrelationWithTheSquaredInput) {
  const Eigen::VectorXd u = 3.0 * sine(2) + 0.5 * sine(7);
  const Record r(u, u, 0.2 * u.cwiseAbs2());
  EXPECT_NEAR(statistic("asymmetry", r).value, 1.0, 1e-9);
}

TEST(EffectSignatures, BacklashFollowsTheDirectionOfMotion) {
  const Eigen::VectorXd u = sine(2);
  Eigen::VectorXd e(kN);
  for (Eigen::Index k = 0; k < kN; ++k) e[k] = k > 0 && u[k] < u[k - 1] ? -0.3 : 0.3;
  EXPECT_GT(statistic("backlash", Record(u, u, e)).value, 0.99);
}

TEST(EffectSignatures, HysteresisFindsTheLoopOfTheInputAndItsWidth) {
  // A loop of half-height r = 1/4 of the input's half range that turns over
  // gradually: the square wave of backlash fits it less well.
  const Eigen::VectorXd u = triangle(400);
  const Record r(u, u, triangle_loop(u, 0.25));
  const SignatureValue loop = statistic("hysteresis", r);
  EXPECT_GT(loop.value, 0.99);
  EXPECT_EQ(detail(loop, "width"), 0.25);
  EXPECT_LT(statistic("backlash", r).value, 0.95);
}

TEST(EffectSignatures, SaturationIsTheTopBinsShareOfTheError) {
  // All the error where |u| > 0.8 (the top of five equal bins of a unit sine):
  // the bin holds 1 − (2/π)·asin(0.8) = 0.4097 of the samples, so the ratio is 1/0.4097.
  const Eigen::VectorXd u = sine(2);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(kN);
  for (Eigen::Index k = 0; k < kN; ++k)
    if (std::abs(u[k]) > 0.8) e[k] = k % 2 ? 0.1 : -0.1;
  const SignatureValue s = statistic("saturation", Record(u, u, e));
  EXPECT_NEAR(s.value, 1.0 / 0.4097, 0.03);
  EXPECT_NEAR(detail(s, "sse_share"), 1.0, 1e-12);
}

TEST(EffectSignatures, CreepFollowsTheInputThroughASlowLag) {
  // A 2 Hz input (8 whole periods, 16 zero crossings): the lag's time constant
  // is one period, τ = 0.5 s. The lagged input, by its recursion
  // x[k] = a x[k−1] + (1 − a) u[k], a = exp(−Ts/τ), x[−1] = u[0], is about 80°
  // behind u and barely correlated with it.
  const Eigen::VectorXd u = sine(2, 0.3);
  const double a = std::exp(-kTs / 0.5);
  Eigen::VectorXd e(kN);
  double x = u[0];
  for (Eigen::Index k = 0; k < kN; ++k) e[k] = x = a * x + (1 - a) * u[k];
  const Record r(u, u, e);
  const SignatureValue s = statistic("creep", r);
  EXPECT_NEAR(s.value, 1.0, 1e-9);
  EXPECT_NEAR(detail(s, "tau"), 0.5, 1e-12);
  EXPECT_LT(std::abs(correlation(e, u)), 0.3);  // cos 80° plus the start-up
}

TEST(EffectSignatures, DelayQuotesThePeakLagAndTheSlope) {
  // A rough input and a residual that is the input 3 samples back.
  const Eigen::VectorXd u = gaussian(1.0, 3);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(kN);
  e.tail(kN - 3) = u.head(kN - 3);
  EXPECT_EQ(detail(statistic("delay", Record(u, u, e)), "lag"), 3);

  // A smooth output measured 5 samples late: e ≈ −0.005 s · dŷ/dt.
  const Eigen::VectorXd y_model = sine(2);
  Eigen::VectorXd late = sine(2, -2 * kPi * 2 * 0.005);
  const SignatureValue s = statistic("delay", Record(y_model, y_model, late - y_model));
  EXPECT_GT(s.value, 0.99);
  EXPECT_NEAR(detail(s, "seconds"), 0.005, 0.0005);
}

TEST(EffectSignatures, MsdFindsTheMissingResonance) {
  // ŷ = a 5 Hz sine with a small 23 Hz one on it (still crossing zero at
  // 5 Hz); y = H·ŷ for H = 1/(1 − (ω/ωn)² + 2jζω/ωn), fn = 40 Hz, ζ = 0.2, in
  // steady state: e = Σ a·|H − 1| sin(ωt + arg(H − 1)).
  const double fn = 40, zeta = 0.2;
  Eigen::VectorXd y_model = Eigen::VectorXd::Zero(kN), e = Eigen::VectorXd::Zero(kN);
  for (const auto& [f, amplitude] : {std::pair{5.0, 1.0}, std::pair{23.0, 0.2}}) {
    const double x = f / fn;
    const std::complex<double> h = 1.0 / std::complex<double>(1 - x * x, 2 * zeta * x);
    y_model += amplitude * sine(f);
    e += amplitude * std::abs(h - 1.0) * sine(f, std::arg(h - 1.0));
  }
  const SignatureValue s = statistic("msd", Record(y_model, y_model, e));
  EXPECT_GT(s.value, 0.95);
  EXPECT_NEAR(detail(s, "f_n"), fn, 4.0);
}

TEST(EffectSignatures, ArxExplainsASecondOrderFilterOfTheOutput) {
  // e = (B/A − 1)·ŷ as a recursion: e[k] = 0.7 e[k−1] − 0.1 e[k−2] + 0.3 ŷ[k−1].
  const Eigen::VectorXd y_model = gaussian(1.0, 4);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(kN);
  for (Eigen::Index k = 2; k < kN; ++k)
    e[k] = 0.7 * e[k - 1] - 0.1 * e[k - 2] + 0.3 * y_model[k - 1];
  EXPECT_GT(statistic("arx", Record(y_model, y_model, e)).value, 0.99);
}

TEST(EffectSignatures, SecondModeFindsANarrowPeakAboveTheBand) {
  // A 5 Hz drive and a residual with a 200 Hz ring in white noise.
  const Eigen::VectorXd u = sine(5);
  const SignatureValue s =
      statistic("second_mode", Record(u, u, 0.05 * sine(200) + gaussian(0.01, 5)));
  EXPECT_GT(s.value, 20.0);
  EXPECT_NEAR(detail(s, "frequency"), 200.0, 4.0);  // bins 1000/256 Hz apart
}

TEST(EffectSignatures, FeedbackHysteresisFindsALoopDrivenByTheOutput) {
  // The output a quarter period behind the input, as near a resonance: the
  // loop of the output is not the loop of the input.
  const Eigen::VectorXd u = triangle(400), y_model = triangle(400, 300);
  const Record r(u, y_model, triangle_loop(y_model, 0.25));
  EXPECT_GT(statistic("feedback_hysteresis", r).value, 0.99);
  EXPECT_LT(std::abs(statistic("hysteresis", r).value), 0.5);
}

TEST(EffectSignatures, DuffingFindsAPolynomialSpringBeyondTheLinearPart) {
  // A residual of ŷ³ (a missing hardening) plus a share of ŷ itself (a gain
  // error), which the statistic leaves to the linear part.
  const Eigen::VectorXd u = sine(5), y_model = sine(5) + 0.3 * sine(13);
  const Eigen::VectorXd cube = y_model.array().cube().matrix();
  const Record r(u, y_model, 0.2 * cube + 0.5 * y_model + gaussian(0.01, 8));
  EXPECT_GT(statistic("duffing", r).value, 0.5);
  const Record linear(u, y_model, 0.5 * y_model + gaussian(0.01, 9));
  EXPECT_LT(statistic("duffing", linear).value, 4 / std::sqrt(double(kN)));
}

// ---- the framework's side ---------------------------------------------------------

TEST(EffectSignatures, AWhiteResidualShowsNoSignOfAnyEffect) {
  const Eigen::VectorXd u = 2.0 * sine(3) + sine(17);
  const Record r(u, u, gaussian(1.0, 6));
  const double chance = 4 / std::sqrt(double(kN));  // 4σ of a correlation
  for (const char* effect : {"offset", "drift", "asymmetry", "backlash", "hysteresis", "creep",
                             "delay", "feedback_hysteresis", "duffing"})
    EXPECT_LT(std::abs(statistic(effect, r).value), chance) << effect;
  EXPECT_LT(std::abs(statistic("msd", r).value), 1.5 * chance);  // the best of 144
  EXPECT_LT(statistic("arx", r).value, 20.0 / double(kN));       // partial R²: χ²(3) / N
  EXPECT_NEAR(statistic("saturation", r).value, 1.0, 0.3);
  EXPECT_LT(statistic("second_mode", r).value, 2.5);  // χ² spread of ~30 averaged segments
}

TEST(EffectSignatures, DynamicsEffectsReadTheSameResidualDifferently) {
  // One 200 Hz ring above a 5 Hz drive: a second mode's narrow peak, not a
  // missing ARX filter or a loop.
  const Eigen::VectorXd u = sine(5);
  const Record r(u, u, 0.05 * sine(200) + gaussian(0.01, 7));
  const double second_mode = statistic("second_mode", r).value, arx = statistic("arx", r).value,
               loop = statistic("feedback_hysteresis", r).value, msd = statistic("msd", r).value;
  EXPECT_GT(second_mode, 20.0);
  EXPECT_LT(arx, 0.05);
  EXPECT_LT(std::abs(loop), 0.1);
  // A resonance would change ŷ at 5 Hz, not at 200 Hz.
  EXPECT_LT(std::abs(msd), 0.1);
}

TEST(EffectSignatures, EveryRegisteredEffectIsCollectedAndWritten) {
  const Eigen::VectorXd u = sine(2);
  const Record r(u, u, 0.3 + gaussian(0.1, 8).array());
  const auto all = effect_signatures(r.view());
  EXPECT_EQ(all.size(), EffectRegistry::instance().all().size());
  const nlohmann::json j = to_json(all);
  for (const auto* info : EffectRegistry::instance().all()) {
    SCOPED_TRACE(info->name);
    ASSERT_TRUE(j.contains(info->name));
    EXPECT_EQ(j[info->name]["statistic"], info->statistic.name);
  }
  EXPECT_NEAR(j["offset"]["value"].get<double>(), 3.0, 0.15);
  const std::string sentence = j["offset"]["sentence"];
  EXPECT_EQ(sentence.find("the residual mean is "), 0u) << sentence;
  EXPECT_NE(sentence.find(" residual standard deviations"), std::string::npos) << sentence;
}

// One row per effect, in the order of the names (as metrics.json keys them).
TEST(EffectSignatures, TheReportTableListsEveryEffect) {
  ComparisonInput in;
  in.t = times();
  in.u = sine(2);
  in.y_model = in.u;
  in.y = in.u + gaussian(0.1, 9);
  const std::string report = comparison_markdown(in, compare_signals(in), "t", "m", false, "");
  std::vector<std::string> names;
  for (const auto* info : EffectRegistry::instance().all()) names.push_back(info->name);
  std::sort(names.begin(), names.end());
  std::size_t previous = 0;
  for (const auto& name : names) {
    const std::size_t at = report.find("| `" + name + "` |");
    ASSERT_NE(at, std::string::npos) << name;
    EXPECT_GT(at, previous) << name;
    previous = at;
  }
}

TEST(EffectSignatures, EvidenceCitesTheCandidatesOwnStatistic) {
  ComparisonInput in;
  in.t = times();
  in.u = sine(2);
  in.y_model = in.u;
  in.y = in.u + 0.5 * in.t + gaussian(0.1, 10);
  const Comparison where = compare_signals(in);
  FitErrors before, after;
  before.rmse_estimation = 1.0;
  after.rmse_estimation = 0.1;
  const auto evidence = [&](const std::string& effect) {
    return evidence_sentence(EffectRegistry::instance().find(effect, "effect"),
                             signature_in(where.signatures, effect), before, after, -50, true,
                             "µm");
  };
  const std::string drift = evidence("drift"), msd = evidence("msd"), arx = evidence("arx");
  EXPECT_NE(drift.find("; here the residual correlates with time (r = 0.9"), std::string::npos)
      << drift;
  EXPECT_NE(msd.find("; here " + signature_in(where.signatures, "msd")->sentence),
            std::string::npos);
  EXPECT_NE(arx.find("; here " + signature_in(where.signatures, "arx")->sentence),
            std::string::npos);
  EXPECT_NE(msd.substr(msd.find("; here")), arx.substr(arx.find("; here")));
}

}  // namespace
}  // namespace hystbench
