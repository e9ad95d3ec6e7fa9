#include "framework/discovery/comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "framework/core/rng.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/stats/residual_correlation.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::TempDir;
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(Eigen::Index(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

Eigen::VectorXd times(Eigen::Index n, double ts) {
  return Eigen::VectorXd::LinSpaced(n, 0.0, double(n - 1) * ts);
}

Eigen::VectorXd gaussian(Eigen::Index n, double sigma, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::VectorXd out(n);
  for (Eigen::Index i = 0; i < n; ++i) out[i] = sigma * rng.normal();
  return out;
}

// Every number in the document is finite (nlohmann::json would print NaN
// as null, so the dump alone cannot show it).
void expect_all_finite(const json& j, const std::string& where = "") {
  if (j.is_number_float()) {
    EXPECT_TRUE(std::isfinite(j.get<double>())) << "non-finite number at " << where;
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      expect_all_finite(it.value(), where + "/" + it.key());
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      expect_all_finite(j[i], where + "/" + std::to_string(i));
  }
}

// A sine input and a static, slightly nonlinear model output.
ComparisonInput sine_case(Eigen::Index n, double ts, double f) {
  ComparisonInput in;
  in.sample_time = ts;
  in.t = times(n, ts);
  in.u = (2 * kPi * f * in.t.array()).sin().matrix() * 100.0;
  in.y_model = 0.02 * in.u + (0.05 * in.u.array()).sin().matrix();
  in.y = in.y_model;
  return in;
}

// ---- error metrics ----------------------------------------------------------

TEST(ComparisonMetrics, HandComputedOnTinyVectors) {
  const Eigen::VectorXd y = vec({1, 2, 3, 4}), yhat = vec({1, 2, 3, 5});
  const ErrorMetrics m = error_metrics(y, yhat);
  // e = (0, 0, 0, -1); y - mean = (-1.5, -0.5, 0.5, 1.5), |.|^2 = 5; |y|^2 = 30.
  EXPECT_EQ(m.n, 4);
  EXPECT_DOUBLE_EQ(m.sse, 1.0);
  EXPECT_DOUBLE_EQ(m.rmse, 0.5);
  EXPECT_NEAR(m.fit_percent, 100.0 * (1.0 - 1.0 / std::sqrt(5.0)), 1e-12);
  EXPECT_NEAR(m.relative_error, 1.0 / std::sqrt(30.0), 1e-15);
  EXPECT_DOUBLE_EQ(m.max_abs_error, 1.0);
  EXPECT_DOUBLE_EQ(m.mean_error, -0.25);

  const ErrorMetrics part = error_metrics(y, yhat, {0, 3});
  // e = (0, -1); y = (1, 4), |y - mean|^2 = 4.5, |y|^2 = 17.
  EXPECT_EQ(part.n, 2);
  EXPECT_DOUBLE_EQ(part.rmse, std::sqrt(0.5));
  EXPECT_NEAR(part.fit_percent, 100.0 * (1.0 - 1.0 / std::sqrt(4.5)), 1e-12);
  EXPECT_NEAR(part.relative_error, 1.0 / std::sqrt(17.0), 1e-15);
}

TEST(ComparisonMetrics, UndefinedNumbersAreNullNotNaN) {
  const Eigen::VectorXd y = vec({2, 2, 2}), yhat = vec({1, 2, 3});
  const json empty = to_json(error_metrics(y, yhat, {}));
  EXPECT_EQ(empty["n"], 0);
  for (const char* key : {"sse", "rmse", "fit_percent", "relative_error", "max_abs_error"})
    EXPECT_TRUE(empty[key].is_null()) << key;

  const json one = to_json(error_metrics(y, yhat, {0}));
  EXPECT_DOUBLE_EQ(one["rmse"].get<double>(), 1.0);
  EXPECT_TRUE(one["fit_percent"].is_null());

  const json constant = to_json(error_metrics(y, yhat));
  EXPECT_TRUE(constant["fit_percent"].is_null());  // y has no spread
  EXPECT_TRUE(constant["relative_error"].is_number());

  const json zero = to_json(error_metrics(Eigen::VectorXd::Zero(3), yhat));
  EXPECT_TRUE(zero["relative_error"].is_null());
}

// ---- compare_signals ----------------------------------------------------------

TEST(ComparisonSignals, DegenerateInputsGiveNaNFreeJson) {
  std::vector<ComparisonInput> cases;
  for (Eigen::Index n : {1, 2, 3, 7}) {
    ComparisonInput in;
    in.t = times(n, 0.01);
    in.u = Eigen::VectorXd::Constant(n, 3.0);  // constant input
    in.y = Eigen::VectorXd::Constant(n, 1.0);  // constant output
    in.y_model = in.y;                         // zero residual
    cases.push_back(in);
  }
  ComparisonInput diverged = sine_case(50, 0.01, 2.0);
  diverged.y_model[10] = kInf;
  cases.push_back(diverged);
  ComparisonInput zeros = sine_case(40, 0.01, 2.0);
  zeros.y.setZero();
  zeros.y_model.setZero();
  zeros.segment.assign(40, "a");
  zeros.estimation = Eigen::VectorXd::Zero(40);
  cases.push_back(zeros);
  for (const auto& in : cases) {
    const json m = to_json(compare_signals(in));
    SCOPED_TRACE("n = " + std::to_string(in.t.size()));
    expect_all_finite(m);
    EXPECT_EQ(json::parse(m.dump()), m);
    EXPECT_TRUE(m["signatures"].is_object());
  }
  // A diverged model is never called white.
  EXPECT_FALSE(compare_signals(diverged).residual.white);
}

TEST(ComparisonSignals, RejectsMismatchedLengths) {
  ComparisonInput in = sine_case(20, 0.01, 1.0);
  in.y_model = Eigen::VectorXd::Zero(19);
  EXPECT_THROW(compare_signals(in), std::invalid_argument);
}

TEST(ComparisonSignals, PartsAndBreakdownsCoverEverySample) {
  ComparisonInput in = sine_case(600, 0.001, 5.0);
  in.y += gaussian(600, 0.1, 11);
  in.segment.assign(600, "a");
  std::fill(in.segment.begin() + 200, in.segment.begin() + 400, "b");
  std::fill(in.segment.begin() + 400, in.segment.end(), "c");
  in.estimation = Eigen::VectorXd::Ones(600);
  in.estimation.segment(300, 300).setZero();  // "b" is half and half, "c" held out
  const Comparison m = compare_signals(in);
  ASSERT_TRUE(m.parts.heldout);
  EXPECT_EQ(m.parts.estimation.n + m.parts.heldout->n, 600);
  const auto sum_n = [](const auto& groups) {
    long n = 0;
    for (const auto& g : groups) n += g.metrics.n;
    return n;
  };
  EXPECT_EQ(sum_n(m.by_amplitude), 600);
  EXPECT_EQ(sum_n(m.by_time), 600);
  EXPECT_EQ(m.by_time.size(), 10u);
  EXPECT_EQ(m.by_branch.loading.n + m.by_branch.unloading.n + m.by_branch.holding.n, 600);
  ASSERT_EQ(m.by_segment.size(), 3u);
  EXPECT_EQ(m.by_segment[0].part, "estimation");
  EXPECT_EQ(m.by_segment[1].part, "mixed");
  EXPECT_EQ(m.by_segment[2].part, "heldout");
  EXPECT_EQ(m.by_segment[2].segment, "c");

  in.estimation.resize(0);  // nothing held out
  const Comparison all_estimation = compare_signals(in);
  EXPECT_FALSE(all_estimation.parts.heldout);
  EXPECT_FALSE(to_json(all_estimation).contains("heldout"));
  EXPECT_FALSE(to_json(all_estimation)["noise_floor"].contains("heldout_rmse_over_sigma"));
}

TEST(ComparisonSignals, BranchesFollowTheSignOfTheInputStep) {
  ComparisonInput in;
  in.t = times(9, 1.0);
  in.u = vec({0, 1, 2, 3, 3, 3, 2, 1, 0});
  in.y = vec({0, 0, 0, 0, 0, 0, 1, 1, 1});  // error only while unloading
  in.y_model = Eigen::VectorXd::Zero(9);
  const BranchErrors b = compare_signals(in).by_branch;
  EXPECT_EQ(b.loading.n, 4);  // the first sample takes the branch of the second
  EXPECT_EQ(b.holding.n, 2);
  EXPECT_EQ(b.unloading.n, 3);
  EXPECT_DOUBLE_EQ(b.unloading.rmse, 1.0);
  EXPECT_DOUBLE_EQ(b.loading.rmse, 0.0);
}

// ---- correlation statistics -----------------------------------------------------

TEST(ComparisonCorrelation, CrossCorrelationPeaksAtTheDelay) {
  const Eigen::Index n = 2000;
  const Eigen::VectorXd u = gaussian(n, 1.0, 7);
  for (int d : {7, -3, 0}) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
    for (Eigen::Index k = 0; k < n; ++k)
      if (k - d >= 0 && k - d < n) e[k] = u[k - d];  // e(k) = u(k - d)
    const Correlation c = cross_correlation(u, e, 25);
    EXPECT_EQ(peak_lag(c), d);
    EXPECT_GT(c.values[std::size_t(d + 25)], 0.95);
    EXPECT_EQ(c.lags.front(), -25);
    EXPECT_EQ(c.lags.back(), 25);
  }
}

TEST(ComparisonCorrelation, WhiteResidualIsWhiteAndAutocorrelatedIsNot) {
  ComparisonInput in = sine_case(3000, 0.001, 3.0);
  const Eigen::VectorXd w = gaussian(3000, 0.05, 2026);
  in.y = in.y_model + w;
  const ResidualAnalysis white = compare_signals(in).residual;
  EXPECT_TRUE(white.white);
  EXPECT_GT(white.ljung_box.p_value, 0.01);
  EXPECT_EQ(white.ljung_box.lags, 20);
  EXPECT_NEAR(white.acf.bound, 2.58 / std::sqrt(3000.0), 1e-12);

  Eigen::VectorXd ar = w;
  for (Eigen::Index k = 1; k < ar.size(); ++k) ar[k] = 0.9 * ar[k - 1] + w[k];
  in.y = in.y_model + ar;
  const ResidualAnalysis coloured = compare_signals(in).residual;
  EXPECT_FALSE(coloured.white);
  EXPECT_LT(coloured.ljung_box.p_value, 1e-6);
  EXPECT_NEAR(coloured.acf.values[0], 0.9, 0.05);
  EXPECT_EQ(coloured.acf.outside, 25);
}

TEST(ComparisonCorrelation, LjungBoxUsesAtMostAFifthOfTheSamples) {
  ComparisonInput in = sine_case(50, 0.01, 2.0);
  in.y += gaussian(50, 0.1, 3);
  EXPECT_EQ(compare_signals(in).residual.ljung_box.lags, 10);
}

// ---- noise floor ----------------------------------------------------------------

TEST(ComparisonNoiseFloor, DifferenceEstimateOnSmoothSignalsIsWithinTenPercent) {
  const Eigen::Index n = 5000;
  const Eigen::VectorXd t = times(n, 0.001);
  const std::vector<Eigen::VectorXd> signals = {
      Eigen::VectorXd((10.0 * (2 * kPi * 2.0 * t.array()).sin()).matrix()),
      Eigen::VectorXd(
          (600.0 * (2 * kPi * 20.0 * t.array()).sin() + 50.0 * (2 * kPi * 3.0 * t.array()).cos())
              .matrix()),
      Eigen::VectorXd((5.0 / (1.0 + (-(t.array() - 2.5) * 8.0).exp())).matrix()),  // smooth step
  };
  std::uint64_t seed = 100;
  for (const auto& s : signals)
    for (double sigma : {0.01, 0.3}) {
      const Eigen::VectorXd y = s + gaussian(n, sigma, ++seed);
      // A non-repeating input: u is the signal itself plus a ramp.
      const Eigen::VectorXd u = s + t;
      const NoiseFloor f = estimate_noise_floor(u, y, {});
      EXPECT_EQ(f.method, "difference_mad");
      EXPECT_NEAR(f.sigma / sigma, 1.0, 0.10) << "sigma " << sigma << " seed " << seed;
    }
}

TEST(ComparisonNoiseFloor, RepeatedPeriodsGiveThePeriodicEstimate) {
  // 20 periods of 100 samples; y has sharp corners that differences cannot remove.
  const Eigen::Index n = 2000, period = 100;
  const Eigen::VectorXd t = times(n, 0.001);
  Eigen::VectorXd u(n), clean(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    u[k] = std::sin(2 * kPi * double(k % period) / double(period));
    clean[k] = u[k] > 0.3 ? 4.0 : -4.0;
  }
  const double sigma = 0.05;
  const Eigen::VectorXd y = clean + gaussian(n, sigma, 77);
  const NoiseFloor f = estimate_noise_floor(u, y, {});
  EXPECT_EQ(f.method, "periodic");
  EXPECT_EQ(f.period, period);
  EXPECT_EQ(f.pairs, (20 - 1 - 10) * period);  // pairs from the second half of the periods
  EXPECT_NEAR(f.sigma / sigma, 1.0, 0.10);

  // Two segments with different periods, each repeating inside its run.
  std::vector<std::string> segment(std::size_t(n), "slow");
  Eigen::VectorXd u2 = u;
  for (Eigen::Index k = 1000; k < n; ++k) {
    segment[std::size_t(k)] = "fast";
    u2[k] = std::sin(2 * kPi * double(k % 40) / 40.0);
  }
  Eigen::VectorXd y2 = y;
  for (Eigen::Index k = 1000; k < n; ++k) y2[k] += (u2[k] > 0.3 ? 4.0 : -4.0) - clean[k];
  const NoiseFloor g = estimate_noise_floor(u2, y2, segment);
  EXPECT_EQ(g.method, "periodic");
  EXPECT_NEAR(g.sigma / sigma, 1.0, 0.10);
}

TEST(ComparisonNoiseFloor, RepeatedSegmentLabelsCountAsPeriods) {
  // Segments "ramp" and "chirp" alternate three times each; the measured input
  // carries a little noise, so it never repeats exactly, but the labels do.
  const Eigen::Index run = 300, n = 6 * run;
  Eigen::VectorXd u(n), clean(n);
  std::vector<std::string> segment;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = k % run;
    const bool ramp = (k / run) % 2 == 0;
    segment.push_back(ramp ? "ramp" : "chirp");
    u[k] = ramp ? double(i) / run : std::sin(0.0002 * double(i * i));
    clean[k] = u[k] > 0.5 ? 3.0 : -1.0;  // corners that differences cannot remove
  }
  u += gaussian(n, 1e-5, 41);
  const double sigma = 0.05;
  const NoiseFloor f = estimate_noise_floor(u, clean + gaussian(n, sigma, 42), segment);
  EXPECT_EQ(f.method, "periodic");
  EXPECT_EQ(f.period, 0);       // not from an exact period of u
  EXPECT_EQ(f.pairs, 2 * run);  // per label: occurrences 2 and 3
  EXPECT_NEAR(f.sigma / sigma, 1.0, 0.10);
}

// Gaussian noise low-passed at `cutoff` (a fraction of fs) by a Hann-windowed
// sinc: no period ever repeats, and above the cutoff the power is gone.
Eigen::VectorXd band_limited_noise(Eigen::Index n, double cutoff, std::uint64_t seed) {
  constexpr int kTaps = 129, kHalf = kTaps / 2;
  std::vector<double> h(kTaps);
  for (int k = 0; k < kTaps; ++k) {
    const double m = k - kHalf;
    const double sinc = m == 0 ? 2 * cutoff : std::sin(2 * kPi * cutoff * m) / (kPi * m);
    h[std::size_t(k)] = sinc * (0.5 - 0.5 * std::cos(2 * kPi * k / (kTaps - 1)));
  }
  const Eigen::VectorXd w = gaussian(n + kTaps, 1.0, seed);
  Eigen::VectorXd u(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < kTaps; ++k) s += h[std::size_t(k)] * w[i + k];
    u[i] = s;
  }
  return u;
}

TEST(ComparisonNoiseFloor, InputAboveASixthOfTheSampleRateGivesTheSpectralEstimate) {
  // As on Silverbox: a band up to 0.3 fs, never repeated, through a lightly
  // damped resonance at 0.1 fs. Differences keep the signal and overestimate σ.
  const Eigen::Index n = 40000;
  const Eigen::VectorXd u = band_limited_noise(n, 0.3, 3);
  const double r = 0.97, a1 = 2 * r * std::cos(2 * kPi * 0.1), a2 = -r * r;
  Eigen::VectorXd clean = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 2; k < n; ++k) clean[k] = a1 * clean[k - 1] + a2 * clean[k - 2] + u[k - 1];
  for (double sigma : {0.01, 0.1}) {
    const NoiseFloor f = estimate_noise_floor(u, clean + gaussian(n, sigma, 9), {});
    EXPECT_EQ(f.method, "spectral");
    EXPECT_NEAR(f.sigma / sigma, 1.0, 0.10) << "sigma " << sigma;
    EXPECT_NEAR(f.quiet_from, 0.3, 0.05);
    EXPECT_GT(difference_noise_floor(clean + gaussian(n, sigma, 9)).sigma, 1.2 * sigma);
  }
  // The same band below fs/6 leaves the difference estimate in charge.
  const Eigen::VectorXd slow = band_limited_noise(n, 0.05, 4);
  EXPECT_EQ(estimate_noise_floor(slow, slow + gaussian(n, 0.01, 5), {}).method, "difference_mad");
}

TEST(ComparisonNoiseFloor, ReportedWithTheRmseRatio) {
  ComparisonInput in = sine_case(4000, 0.001, 2.0);
  in.y += gaussian(4000, 0.2, 5);
  const ComparedNoiseFloor f = compare_signals(in).noise_floor;
  EXPECT_EQ(f.method, "periodic");  // 2 Hz at 1 kHz repeats every 500 samples
  EXPECT_NEAR(f.sigma / 0.2, 1.0, 0.10);
  EXPECT_NEAR(f.rmse_over_sigma, 1.0, 0.10);  // a perfect model
}

// ---- signatures -------------------------------------------------------------------

// Every registered effect's statistic is in metrics.json under the effect's
// name; each catalog effect's own statistic rises when its effect is hidden in
// the data (effect_signatures_test.cpp checks the statistics one by one).
TEST(ComparisonSignatures, EachHiddenEffectRaisesItsOwnStatistic) {
  const ComparisonInput base = [] {
    ComparisonInput in = sine_case(4000, 0.001, 2.0);
    in.y += gaussian(4000, 0.05, 99);
    return in;
  }();
  const json clean = to_json(compare_signals(base).signatures);
  for (const char* effect : {"offset", "drift", "asymmetry", "backlash"})
    EXPECT_LT(std::abs(clean[effect]["value"].get<double>()), 0.2) << effect;
  for (auto it = clean.begin(); it != clean.end(); ++it) {
    EXPECT_FALSE(it.value()["statistic"].get<std::string>().empty()) << it.key();
    EXPECT_TRUE(it.value()["sentence"].is_string()) << it.key();
  }

  const auto with = [&](auto effect) {
    ComparisonInput in = base;
    effect(in);
    return to_json(compare_signals(in).signatures);
  };
  const auto value = [](const json& signatures, const char* effect) {
    return signatures[effect]["value"].get<double>();
  };
  EXPECT_GT(value(with([](ComparisonInput& in) { in.y.array() += 0.3; }), "offset"), 2.0);
  EXPECT_GT(value(with([](ComparisonInput& in) { in.y += 0.5 * in.t; }), "drift"), 0.8);
  EXPECT_GT(value(with([](ComparisonInput& in) { in.y += 1e-4 * in.u.cwiseAbs2(); }), "asymmetry"),
            0.8);
  EXPECT_GT(value(with([](ComparisonInput& in) {
                    for (Eigen::Index k = 1; k < in.y.size(); ++k)
                      in.y[k] += in.u[k] > in.u[k - 1] ? 0.3 : -0.3;
                  }),
                  "backlash"),
            0.8);
  const json saturated = with([](ComparisonInput& in) {
    in.y_model = 0.02 * in.u;
    in.y = (2.0 * (0.01 * in.u.array()).tanh()).matrix();  // same slope at 0, saturates at ±2
  });
  EXPECT_GT(value(saturated, "saturation"), 1.5);
  EXPECT_GT(saturated["saturation"]["details"]["sse_share"].get<double>(),
            saturated["saturation"]["details"]["sample_share"].get<double>());

  // A measured output 5 samples late: e ≈ −d·dŷ/dt with d = 5 ms.
  const json delayed = with([](ComparisonInput& in) {
    for (Eigen::Index k = 0; k < in.y.size(); ++k)
      in.y[k] = in.y_model[std::max<Eigen::Index>(0, k - 5)];
  });
  EXPECT_NEAR(delayed["delay"]["details"]["seconds"].get<double>(), 0.005, 0.001);
  EXPECT_GT(value(delayed, "delay"), 0.9);
  EXPECT_NE(delayed["delay"]["sentence"].get<std::string>().find("−dŷ/dt"), std::string::npos);
}

// ---- report ----

TEST(ComparisonReport, VerdictsFollowTheNumbers) {
  ComparisonInput in = sine_case(3000, 0.001, 2.0);
  in.y += gaussian(3000, 0.05, 21);
  const Comparison good = compare_signals(in);
  const std::string white = comparison_markdown(in, good, "t", "m", false, "");
  EXPECT_NE(white.find("the residual is white"), std::string::npos);
  EXPECT_NE(white.find("at the noise floor"), std::string::npos);
  EXPECT_EQ(white.find("!["), std::string::npos);  // no images to embed

  in.y += 0.3 * in.u.cwiseAbs2() / 100.0;  // a large missing even term
  const Comparison bad = compare_signals(in);
  const std::string coloured = comparison_markdown(in, bad, "t", "m", true, "");
  EXPECT_NE(coloured.find("**not white**"), std::string::npos);
  EXPECT_NE(coloured.find("well above the noise floor"), std::string::npos);
  EXPECT_NE(coloured.find("![Residual over time"), std::string::npos);
}

// ---- report writing ------------------------------------------------------------------------

bool gnuplot_installed() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

using hystbench::test_support::read;

TEST(ComparisonReport, WritesMetricsReportAndFigures) {
  TempDir tmp;
  ComparisonInput in = sine_case(3000, 0.001, 2.0);
  in.u_unit = "V";
  in.y_unit = "µm";
  in.y += gaussian(3000, 0.05, 8) + 1e-4 * in.u.cwiseAbs2();
  in.segment.assign(3000, "sine_2Hz");
  std::fill(in.segment.begin() + 1500, in.segment.end(), "sine|5Hz");
  for (Eigen::Index k = 1500; k < 3000; ++k) in.u[k] = 100 * std::sin(2 * kPi * 5.0 * in.t[k]);
  in.estimation = Eigen::VectorXd::Ones(3000);
  in.estimation.tail(1000).setZero();
  const Comparison m = compare_signals(in);
  const fs::path dir = tmp.path() / "compare";
  const auto files = write_comparison(dir, in, m, "Synthetic test", "hysteresis,msd");
  for (const auto& f : files) EXPECT_TRUE(fs::exists(f)) << f;

  EXPECT_EQ(read(dir / "metrics.json"), to_json(m).dump(2) + "\n");
  const std::string report = read(dir / "report.md");
  for (const char* part : {"# Synthetic test", "`hysteresis,msd`", "| held out |", "Noise floor",
                           "Ljung–Box", "sine\\|5Hz", "| loading |", "asymmetry", "residual.svg"})
    EXPECT_NE(report.find(part), std::string::npos) << part;
  for (const char* name :
       {"fit_model_time", "fit_model_loops", "residual", "segment_rmse", "correlation"}) {
    EXPECT_TRUE(fs::exists(dir / (std::string(name) + ".gp"))) << name;
    if (gnuplot_installed()) {
      EXPECT_GT(fs::file_size(dir / (std::string(name) + ".png")), 1000u) << name;
    }
  }
  if (gnuplot_installed()) {
    EXPECT_FALSE(fs::exists(dir / "gnuplot.log")) << read(dir / "gnuplot.log");
    EXPECT_NE(report.find("![Residual over time"), std::string::npos);
  }
}

}  // namespace
}  // namespace hystbench
