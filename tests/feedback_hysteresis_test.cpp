// The feedback_hysteresis effect (Bouc-Wen oscillator) and the cubic-spline
// input interpolation it integrates with.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "framework/model/input_interpolation.hpp"
#include "framework/model/model.hpp"
#include "tests/input_record.hpp"

namespace hystbench {
namespace {

// gain, period, zeta, alpha, beta_gamma, beta_delta.
Eigen::VectorXd params(double fn, double zeta, double alpha, double bg, double bd,
                       double gain = 1.0) {
  Eigen::VectorXd x(6);
  x << gain, 1.0 / fn, zeta, alpha, bg, bd;
  return x;
}

// A random-phase-like multisine with RMS about 1, 5-150 Hz at fs = 1 kHz.
Eigen::VectorXd multisine(Eigen::Index n, double ts, double scale = 1.0) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 12; ++i) {
    const double f = 5.0 + 12.5 * i, phase = 0.7 * i * i;
    for (Eigen::Index k = 0; k < n; ++k)
      u[k] += scale * 0.41 * std::sin(2.0 * std::numbers::pi * f * ts * double(k) + phase);
  }
  return u;
}

Model model() { return Model::parse("feedback_hysteresis"); }

TEST(FeedbackHysteresis, DeclaresMsdParameterNamesAndExtendsMsd) {
  const Model m = model();
  const std::vector<std::string> names = {
      "gain", "feedback_hysteresis.period", "feedback_hysteresis.zeta",
      "feedback_hysteresis.alpha", "feedback_hysteresis.beta_gamma",
      "feedback_hysteresis.beta_delta"};
  EXPECT_EQ(m.parameter_names(), names);
  EXPECT_EQ(EffectRegistry::instance().find("feedback_hysteresis", "test").extends, "msd");
  EXPECT_EQ(m.neutral()[3], 0.0);  // alpha = 0: no hysteresis
  EXPECT_TRUE(m.bounds().contains(m.neutral()));
}

TEST(FeedbackHysteresis, WithNoLoopItIsReadAsASpringNotHysteresis) {
  const auto& reading = EffectRegistry::instance().find("feedback_hysteresis", "test").reading;
  ASSERT_TRUE(reading);
  const auto read = [&](double alpha, double bg, double bd) {
    const std::vector<double> p = {0.01, 0.1, alpha, bg, bd};
    return reading(p);
  };
  // dz/dy grows with |z| when β·δ < 0: the stiffness hardens.
  EXPECT_NE(read(0.5, 0.16, -11.3).find("a hardening spring, not hysteresis"), std::string::npos);
  EXPECT_NE(read(0.5, 0.0, 2.0).find("a softening spring, not hysteresis"), std::string::npos);
  EXPECT_NE(read(0.5, 0.0, 0.0).find("a linear spring"), std::string::npos);
  EXPECT_EQ(read(0.5, 1.0, 0.5), "");   // a loop: the name says it
  EXPECT_EQ(read(0.0, 0.0, -2.0), "");  // no hysteretic force at all
}

TEST(FeedbackHysteresis, StepResponseAtZeroAlphaMatchesAnalyticSecondOrder) {
  const double ts = 1e-3;
  const Eigen::Index n = 3000;
  // A constant input from t = 0 with the state at rest is an exact step.
  const ModelData d = input_record(Eigen::VectorXd::Constant(n, 1.0), ts);
  // Unit static gain: the response settles at 1 (checked within the record
  // for the better-damped cases).
  for (const double zeta : {0.05, 0.3, 0.9}) {
    const double fn = 7.0, wn = 2.0 * std::numbers::pi * fn;
    Eigen::VectorXd y;
    ASSERT_TRUE(model().simulate(params(fn, zeta, 0.0, 0.7, -0.4), d, y));
    const double wd = wn * std::sqrt(1.0 - zeta * zeta);
    double worst = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double t = ts * double(k);
      const double exact =
          1.0 - std::exp(-zeta * wn * t) *
                    (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
      worst = std::max(worst, std::abs(y[k] - exact));
    }
    EXPECT_LT(worst, 1e-6) << "zeta " << zeta;
    if (zeta > 0.1) {
      EXPECT_NEAR(y[n - 1], 1.0, 1e-6) << "unit static gain, zeta " << zeta;
    }
  }
}

TEST(FeedbackHysteresis, OverdampedStepResponseMatchesAnalytic) {
  const double ts = 1e-3, fn = 20.0, zeta = 1.5, wn = 2.0 * std::numbers::pi * fn;
  const ModelData d = input_record(Eigen::VectorXd::Constant(500, 1.0), ts);
  Eigen::VectorXd y;
  ASSERT_TRUE(model().simulate(params(fn, zeta, 0.0, 0.0, 0.0), d, y));
  const double s = std::sqrt(zeta * zeta - 1.0);
  const double p1 = -wn * (zeta - s), p2 = -wn * (zeta + s);
  for (Eigen::Index k = 0; k < d.size(); ++k) {
    const double t = ts * double(k);
    const double exact = 1.0 + (p2 * std::exp(p1 * t) - p1 * std::exp(p2 * t)) / (p1 - p2);
    ASSERT_NEAR(y[k], exact, 1e-6) << "sample " << k;
  }
}

TEST(FeedbackHysteresis, SubstepsConvergeOnAMultisineWithHysteresis) {
  const double ts = 1.0 / 750.0;
  const ModelData d = input_record(multisine(8000, ts), ts);
  // Benchmark-like: resonance about 25 Hz, strong hysteresis.
  const Eigen::VectorXd x = params(25.0, 0.016, 1.0, 0.53, -0.73, 1.5);
  Model m20 = model(), m40 = model();
  m20.set_substeps(20);
  m40.set_substeps(40);
  Eigen::VectorXd y20, y40, ydefault;
  ASSERT_TRUE(m20.simulate(x, d, y20));
  ASSERT_TRUE(m40.simulate(x, d, y40));
  ASSERT_TRUE(model().simulate(x, d, ydefault));
  const double rms = std::sqrt(y40.squaredNorm() / double(d.size()));
  EXPECT_GT(rms, 0.1);
  EXPECT_LT((y20 - y40).cwiseAbs().maxCoeff(), 1e-6 * rms);
  // The default takes 3 sub-steps here (0.1 rad of the fastest linear mode
  // each); the strong loop moves faster, and the error is 5e-5 of the RMS.
  EXPECT_LT((ydefault - y40).cwiseAbs().maxCoeff(), 1e-4 * rms);
  EXPECT_GT((ydefault - y40).cwiseAbs().maxCoeff(), (y20 - y40).cwiseAbs().maxCoeff()) << "fewer than 20";
  // Hysteresis changes the response noticeably.
  Eigen::VectorXd ylin;
  ASSERT_TRUE(m20.simulate(params(25.0, 0.016, 0.0, 0.53, -0.73, 1.5), d, ylin));
  EXPECT_GT((ylin - y20).norm(), 0.1 * y20.norm());
}

TEST(FeedbackHysteresis, ExactlyLinearAtNeutralAlpha) {
  const double ts = 1e-3;
  const Eigen::VectorXd u1 = multisine(4000, ts), u2 = multisine(4000, ts).reverse();
  const Model m = model();
  for (const Eigen::VectorXd& x : {params(30.0, 0.1, 0.0, 2.0, -2.0), m.neutral()}) {
    Eigen::VectorXd y1, y2, y12;
    ASSERT_TRUE(m.simulate(x, input_record(u1, ts), y1));
    ASSERT_TRUE(m.simulate(x, input_record(u2, ts), y2));
    ASSERT_TRUE(m.simulate(x, input_record(2.0 * u1 - 3.0 * u2, ts), y12));
    EXPECT_LT((y12 - (2.0 * y1 - 3.0 * y2)).cwiseAbs().maxCoeff(), 1e-12 * y12.cwiseAbs().maxCoeff());
  }
  // With alpha > 0 it is not.
  const Eigen::VectorXd x = params(30.0, 0.1, 1.0, 0.5, 0.2);
  Eigen::VectorXd y1, y2;
  ASSERT_TRUE(m.simulate(x, input_record(u1, ts), y1));
  ASSERT_TRUE(m.simulate(x, input_record(2.0 * u1, ts), y2));
  EXPECT_GT((y2 - 2.0 * y1).norm(), 1e-3 * y2.norm());
}

TEST(FeedbackHysteresis, NeutralIsAnExactPassThrough) {
  const double ts = 1e-3;
  Eigen::VectorXd u(2000);
  for (Eigen::Index k = 0; k < u.size(); ++k) u[k] = std::sin(2.0 * std::numbers::pi * 2.0 * ts * double(k));
  Eigen::VectorXd y;
  const Model m = model();
  ASSERT_TRUE(m.simulate(m.neutral(), input_record(u, ts), y));
  EXPECT_EQ(y, u);  // period 0: infinitely stiff
}

TEST(FeedbackHysteresis, InvalidOrDivergingParametersFail) {
  const double ts = 1e-3;
  const ModelData d = input_record(multisine(3000, ts, 3.0), ts);
  const Model m = model();
  Eigen::VectorXd y;
  EXPECT_FALSE(m.simulate(params(30.0, 0.0, 0.5, 0.1, 0.1), d, y)) << "zeta = 0";
  EXPECT_FALSE(m.simulate(params(30.0, -0.1, 0.5, 0.1, 0.1), d, y)) << "negative damping";
  EXPECT_FALSE(m.simulate(params(30.0, 0.1, NAN, 0.1, 0.1), d, y)) << "NaN";
  EXPECT_FALSE(m.simulate(params(30.0, 0.1, 0.5, INFINITY, 0.1), d, y)) << "inf";
  EXPECT_FALSE(m.simulate(params(1e9, 0.1, 0.5, 0.1, 0.1), d, y)) << "far too stiff";
  // beta_delta strongly negative: z grows exponentially with the displacement.
  EXPECT_FALSE(m.simulate(params(30.0, 0.1, 4.0, -3.0, -3.0, 20.0), d, y)) << "diverges";
  // Valid parameters at the bounds' corners simulate to finite values.
  const Bounds b = m.bounds();
  for (int corner = 0; corner < 64; ++corner) {
    Eigen::VectorXd x(6);
    for (int j = 0; j < 6; ++j) x[j] = (corner >> j) & 1 ? b.upper[j] : b.lower[j];
    x[0] = 1.0;
    if (m.simulate(x, d, y)) {
      EXPECT_TRUE(y.allFinite()) << x.transpose();
    }
  }
}

// A fixed sub-step count raises a stiff oscillator to at most ten times
// itself: at 5, an oscillator needing 26 sub-steps runs and one needing 68 is
// refused; by default (no fixed count) both run.
TEST(FeedbackHysteresis, AFixedCountRaisesAStiffOscillatorOnlyTenfold) {
  const double ts = 1e-3;
  const ModelData d = input_record(multisine(500, ts, 3.0), ts);
  Model fixed = model();
  fixed.set_substeps(5);
  const Model by_default = model();
  Eigen::VectorXd y;
  const Eigen::VectorXd stiff26 = params(3000.0, 0.1, 0.5, 0.1, 0.1), stiff68 = params(8000.0, 0.1, 0.5, 0.1, 0.1);
  EXPECT_TRUE(fixed.simulate(stiff26, d, y));
  EXPECT_FALSE(fixed.simulate(stiff68, d, y));
  EXPECT_TRUE(by_default.simulate(stiff26, d, y));
  EXPECT_TRUE(by_default.simulate(stiff68, d, y));
}

TEST(FeedbackHysteresis, SplineReproducesACubicPolynomial) {
  auto cubic = [](double k) { return 1.0 + 2.0 * k - 0.5 * k * k + 0.03 * k * k * k; };
  for (const Eigen::Index n : {4, 5, 6, 50}) {
    Eigen::VectorXd w(n);
    for (Eigen::Index k = 0; k < n; ++k) w[k] = cubic(double(k));
    const UniformCubicSpline s(w);
    for (double pos = 0.0; pos <= double(n - 1); pos += 0.0625)
      ASSERT_NEAR(s(pos), cubic(pos), 1e-9 * (1.0 + std::abs(cubic(pos))))
          << "n " << n << " at " << pos;
    const auto c = UniformCubicSpline::weights(0.3);
    EXPECT_NEAR(s.value(1, c), cubic(1.3), 1e-9);
  }
  // Three samples: the parabola through them.
  const UniformCubicSpline p(Eigen::Vector3d(1.0, 0.0, 3.0));
  EXPECT_NEAR(p(0.5), 2.0 * 0.25 - 3.0 * 0.5 + 1.0 + 0.0, 1e-12);  // 2k^2 - 3k + 1
  EXPECT_NEAR(p(1.5), 2.0 * 2.25 - 4.5 + 1.0, 1e-12);
  // Passes through the samples of arbitrary data.
  const Eigen::VectorXd r = multisine(100, 1e-3);
  const UniformCubicSpline sr(r);
  for (Eigen::Index k = 0; k < r.size(); ++k) ASSERT_NEAR(sr(double(k)), r[k], 1e-12);
}

}  // namespace
}  // namespace hystbench
