// The duffing effect: a mass-spring-damper with a polynomial spring, on the
// oscillator it shares with feedback_hysteresis.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/model_fit.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/model/model.hpp"
#include "tests/input_record.hpp"

namespace hystbench {
namespace {

// gain, period, zeta, k2, k3, drag.
Eigen::VectorXd params(double fn, double zeta, double k2, double k3, double gain = 1.0, double drag = 0.0) {
  Eigen::VectorXd x(6);
  x << gain, 1.0 / fn, zeta, k2, k3, drag;
  return x;
}

Eigen::VectorXd multisine(Eigen::Index n, double ts) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 8; ++i) {
    const double f = 4.0 + 9.0 * i, phase = 0.9 * i * i;
    for (Eigen::Index k = 0; k < n; ++k) u[k] += 0.5 * std::sin(2.0 * std::numbers::pi * f * ts * double(k) + phase);
  }
  return u;
}

Model model() { return Model::parse("duffing"); }

TEST(Duffing, DeclaresMsdParameterNamesAndExtendsMsd) {
  const Model m = model();
  const std::vector<std::string> names = {"gain",       "duffing.period", "duffing.zeta",
                                          "duffing.k2", "duffing.k3",     "duffing.drag"};
  EXPECT_EQ(m.parameter_names(), names);
  EXPECT_EQ(EffectRegistry::instance().find("duffing", "test").extends, "msd");
  EXPECT_TRUE(m.bounds().contains(m.neutral()));
  Eigen::VectorXd y;
  const Eigen::VectorXd u = multisine(500, 1e-3);
  ASSERT_TRUE(m.simulate(m.neutral(), input_record(u, 1e-3), y));
  EXPECT_EQ(y, u) << "period 0 passes the input through";
}

// A constant drive from rest, well damped, settles where the spring force
// y + k2 y² + k3 y³ equals it: the roots worked out by hand.
TEST(Duffing, AConstantDriveSettlesOnTheSpringsStaticCurve) {
  struct Case {
    double k2, k3, w, y;
  };
  for (const Case c : {Case{0.0, 1.0, 2.0, 1.0},           // y + y³ = 2
                       Case{0.5, 0.0, 4.0, 2.0},           // y + y²/2 = 4
                       Case{0.0, -0.1, 0.9, 1.0},          // softening: y − y³/10 = 0.9
                       Case{-0.2, 0.3, 2.0625, 1.5}}) {    // 1.5 − 0.45 + 1.0125
    const double ts = 1e-3;
    const ModelData d = input_record(Eigen::VectorXd::Constant(3000, c.w), ts);
    Eigen::VectorXd y;
    ASSERT_TRUE(model().simulate(params(7.0, 0.9, c.k2, c.k3), d, y));
    EXPECT_NEAR(y[y.size() - 1], c.y, 1e-9) << "k2 " << c.k2 << ", k3 " << c.k3;
  }
}

// Without its nonlinear terms the spring is the Bouc-Wen oscillator without
// hysteresis, bit for bit: the same integration runs both.
TEST(Duffing, WithALinearSpringItIsTheFeedbackOscillatorWithoutALoop) {
  const double ts = 1.0 / 750.0;
  const ModelData d = input_record(multisine(3000, ts), ts);
  Eigen::VectorXd bouc_wen(6);
  bouc_wen << 1.5, 1.0 / 25.0, 0.05, 0.0, 0.0, 0.0;
  Eigen::VectorXd y_duffing, y_bouc_wen;
  ASSERT_TRUE(model().simulate(params(25.0, 0.05, 0.0, 0.0, 1.5), d, y_duffing));
  ASSERT_TRUE(Model::parse("feedback_hysteresis").simulate(bouc_wen, d, y_bouc_wen));
  EXPECT_EQ(y_duffing, y_bouc_wen);
  Eigen::VectorXd y_hard;
  ASSERT_TRUE(model().simulate(params(25.0, 0.05, 0.0, 0.5, 1.5), d, y_hard));
  EXPECT_GT((y_hard - y_duffing).norm(), 0.05 * y_duffing.norm()) << "k3 changes the response";
}

TEST(Duffing, ASofteningSpringThatEscapesFails) {
  const double ts = 1e-3;
  const ModelData d = input_record(Eigen::VectorXd::Constant(2000, 2.0), ts);
  Eigen::VectorXd y;
  // y − y³ peaks at 0.385: a drive of 2 pushes the mass over the barrier.
  EXPECT_FALSE(model().simulate(params(7.0, 0.5, 0.0, -1.0), d, y));
  EXPECT_FALSE(model().simulate(params(7.0, 0.5, NAN, 0.1), d, y));
}

TEST(Duffing, TheReadingNamesAHardeningOrSofteningSpring) {
  const auto& reading = EffectRegistry::instance().find("duffing", "test").reading;
  ASSERT_TRUE(reading);
  const auto read = [&](double k2, double k3, double drag = 0.0) {
    const std::vector<double> p = {0.01, 0.1, k2, k3, drag};
    return reading(p);
  };
  // At twice the RMS: 1 + 2·k2·2 + 3·k3·4 above rest, 1 − 2·k2·2 + 3·k3·4 below.
  EXPECT_NE(read(-0.1, 0.5).find("is a hardening spring (k2 = -0.1, k3 = 0.5, normalised): at twice the "
                                 "output's RMS its stiffness is 6.6 times the linear one above rest and 7.4 "
                                 "times below"),
            std::string::npos)
      << read(-0.1, 0.5);
  EXPECT_NE(read(0.0, -0.05).find("a softening spring"), std::string::npos);
  EXPECT_EQ(read(0.0, 0.0), "");
  // drag / (2 zeta) = 0.02 / 0.2.
  EXPECT_NE(read(0.0, 0.5, 0.02).find("hardening spring"), std::string::npos);
  EXPECT_NE(read(0.0, 0.5, 0.02).find("; a quadratic drag (0.02, normalised) adds 10 % to the linear damping"),
            std::string::npos)
      << read(0.0, 0.5, 0.02);
  EXPECT_EQ(read(0.0, 0.0, 0.02).rfind("is a linear spring with a quadratic drag", 0), 0u) << read(0.0, 0.0, 0.02);
}

// Driven at its resonance, a linear spring with a quadratic drag settles
// where the equivalent viscous damping balances the drive (harmonic
// balance: the fundamental of v|v| for v = V sin is 8/(3 pi) V²). With
// w = F sin(wn t) and y = A cos(wn t): A (2 zeta + 8 drag A / (3 pi)) = F.
TEST(Duffing, ADragLimitsTheResonanceAsHarmonicBalanceSays) {
  const double zeta = 0.05, drag = 0.2, force = 0.1, fn = 10.0, ts = 1.0 / 400.0;
  const Eigen::Index n = 8000, period = 40;  // 200 periods; the last 20 are measured
  Eigen::VectorXd u(n);
  for (Eigen::Index k = 0; k < n; ++k) u[k] = force * std::sin(2.0 * std::numbers::pi * fn * ts * double(k));
  const auto amplitude = [&](double d) {
    Eigen::VectorXd y;
    EXPECT_TRUE(model().simulate(params(fn, zeta, 0.0, 0.0, 1.0, d), input_record(u, ts), y));
    return y.tail(20 * period).cwiseAbs().maxCoeff();
  };
  const double b = 8.0 * drag / (3.0 * std::numbers::pi);
  const double expected = (-2.0 * zeta + std::sqrt(4.0 * zeta * zeta + 4.0 * b * force)) / (2.0 * b);
  EXPECT_NEAR(amplitude(drag), expected, 0.02 * expected);
  EXPECT_NEAR(amplitude(0.0), force / (2.0 * zeta), 0.01 * force / (2.0 * zeta)) << "without the drag: F / 2 zeta";
}

// A fit recovers a planted spring and drag from a three-sine record to the
// noise.
TEST(Duffing, AFitRecoversAPlantedSpring) {
  const nlohmann::json excitation = {
      {"sample_rate", 500},
      {"segments",
       {{{"type", "sine"}, {"frequency", 3}, {"amplitude", 50}, {"duration", 1}},
        {{"type", "sine"}, {"frequency", 12}, {"amplitude", 60}, {"duration", 1}},
        {{"type", "sine"}, {"frequency", 30}, {"amplitude", 30}, {"duration", 1}}}}};
  const Model m = model();
  const nlohmann::json truth = {{"gain", 0.5},
                                {"duffing.period", 0.025},
                                {"duffing.zeta", 0.2},
                                {"duffing.k2", -0.004},
                                {"duffing.k3", 0.0015},
                                {"duffing.drag", 0.003}};
  const SyntheticData s = make_model_synthetic_data(m, truth, excitation, 0.01, 7, "test");
  const ModelData d(s.data, SignalScales::of(s.data));
  FitOptions o;
  o.restarts = 2;
  o.evaluations = 3000;
  o.local_evaluations = 1500;
  o.seed = 11;
  const FitResult r = fit_model(m, d, o);
  const double sd = s.truth["noise"]["sd"];
  EXPECT_LT(fit_errors(r.model, r.x, d).rmse_estimation, 1.05 * sd);
  const auto values = r.model.physical_values(r.x, d.scales);
  EXPECT_NEAR(values["duffing.k3"].get<double>(), 0.0015, 0.0015 * 0.05);
  EXPECT_NEAR(values["duffing.k2"].get<double>(), -0.004, 0.004 * 0.1);
  EXPECT_NEAR(values["duffing.period"].get<double>(), 0.025, 0.025 * 0.01);
  EXPECT_NEAR(values["duffing.drag"].get<double>(), 0.003, 0.003 * 0.1);
}

}  // namespace
}  // namespace hystbench
