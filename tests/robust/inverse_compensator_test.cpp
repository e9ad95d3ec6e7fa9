// Inverse compensation (framework/tracking/inverse_compensator.hpp): for
// every family of fronts in the catalog, the model driven by the inverse's
// output gives back the desired signal to the inversion tolerance, and a
// strictly increasing front gives back the input itself.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <ostream>
#include <numbers>

#include "framework/core/error.hpp"
#include "framework/svr/svr_model.hpp"
#include "framework/tracking/inverse_compensator.hpp"

namespace hystbench {
namespace {

constexpr double kTs = 1e-4, kTolerance = 1e-9;

std::unique_ptr<IdentifiedModel> model(const std::string& effects, nlohmann::json values) {
  values["gain"] = 1.0;
  return read_identified({{"model", effects}, {"parameters", values}}, ".", "test").make(kTs);
}

// Two periods of a sine with a harmonic, inside [0.2, 2.8].
double drive(int k) {
  const double t = k * kTs;
  return 1.5 + std::sin(2 * std::numbers::pi * 5 * t) + 0.3 * std::sin(2 * std::numbers::pi * 15 * t);
}

struct Family {
  std::string effects;
  nlohmann::json values;
  bool strictly_increasing;
};

// gtest prints a parameter in failure messages and test listings.
void PrintTo(const Family& f, std::ostream* os) { *os << f.effects; }

class InverseFamily : public testing::TestWithParam<Family> {};

TEST_P(InverseFamily, ModelOfTheInverseGivesBackTheDesiredSignal) {
  const auto truth = model(GetParam().effects, GetParam().values);
  const auto check = truth->clone();
  InverseCompensator inverse(*truth, GetParam().effects, 0.0, 3.0, kTolerance);
  double worst_w = 0.0, worst_u = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double u = drive(k), w = truth->step_front(u);
    const double u_back = inverse.step(w);
    worst_w = std::max(worst_w, std::abs(check->step_front(u_back) - w));
    worst_u = std::max(worst_u, std::abs(u_back - u));
  }
  EXPECT_LE(worst_w, kTolerance);
  EXPECT_EQ(inverse.statistics().saturated, 0);
  EXPECT_LE(inverse.statistics().max_residual, kTolerance);
  EXPECT_GT(inverse.statistics().samples, 0);
  if (GetParam().strictly_increasing) {
    EXPECT_LE(worst_u, 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Catalog, InverseFamily,
    testing::Values(Family{"none", nlohmann::json::object(), true},
                    Family{"hysteresis", {{"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}}, true},
                    Family{"hysteresis,asymmetry",
                           {{"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}, {"asymmetry.d2", 0.1}},
                           true},
                    Family{"hysteresis,saturation",
                           {{"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}, {"saturation.lambda", 0.1}, {"saturation.softness", 0.4}},
                           true},
                    // The play is flat inside its dead band: the inverse is not unique there.
                    Family{"backlash,hysteresis",
                           {{"backlash.r", 0.1}, {"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}},
                           false}),
    [](const testing::TestParamInfo<Family>& info) {
      std::string name = info.param.effects;
      for (char& c : name)
        if (c == ',') c = '_';
      return name;
    });

// The SVR family: a stage 1 trained on three periods of a hysteretic
// record, its front driven by a fresh input and inverted again.
TEST(Inverse, SvrModelOfTheInverseGivesBackTheDesiredSignal) {
  const double ts = 5e-3;
  const int n = 600;
  Eigen::VectorXd x(n), y(n);
  auto truth = model("hysteresis", {{"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}});
  for (int k = 0; k < n; ++k) {
    x[k] = 1.5 - 1.5 * std::cos(2 * std::numbers::pi * k * ts);
    y[k] = truth->step_front(x[k]);
  }
  SvrHyperparameters h;
  h.epsilon = 1e-3, h.C = 100, h.sigma = 3;
  const SvrHammerstein svr = SvrHammerstein::fit_stage1(x, y, SvrLags{2, 2}, h, "test");
  const std::string file = testing::TempDir() + "/inverse_svr_model.json";
  nlohmann::json j = svr.to_json();
  j["sample_time"] = ts;
  std::ofstream(file) << j.dump();
  const auto m = read_identified({{"svr", file}}, ".", "test").make(ts);
  const auto driven = m->clone(), check = m->clone();
  InverseCompensator inverse(*m, "svr", 0.0, 3.0, kTolerance);
  double worst = 0.0;
  for (int k = 0; k < 400; ++k) {
    const double u = 1.5 - 1.2 * std::cos(2 * std::numbers::pi * 1.3 * k * ts);
    const double w = driven->step_front(u);
    worst = std::max(worst, std::abs(check->step_front(inverse.step(w)) - w));
  }
  EXPECT_EQ(inverse.statistics().saturated, 0);
  EXPECT_LE(worst, kTolerance);
}

TEST(Inverse, BeyondTheRangeTakesTheNearerEndAndCountsTheSample) {
  const auto m = model("none", nlohmann::json::object());
  InverseCompensator inverse(*m, "none", 0.0, 3.0, kTolerance);
  EXPECT_EQ(inverse.step(5.0), 3.0);
  EXPECT_EQ(inverse.step(-1.0), 0.0);
  EXPECT_NEAR(inverse.step(1.25), 1.25, 1e-12);
  EXPECT_EQ(inverse.statistics().saturated, 2);
  EXPECT_EQ(inverse.statistics().samples, 3);
}

TEST(Inverse, RefusesAFrontThatIgnoresTheCurrentInput) {
  const auto m = model("delay", {{"delay.d", 2.0}});
  try {
    InverseCompensator inverse(*m, "delay", 0.0, 3.0, kTolerance);
    FAIL() << "a two-sample input delay was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not respond to the current input"), std::string::npos) << e.what();
  }
}

TEST(Inverse, TrialLeavesTheStateAsItWas) {
  const auto m = model("hysteresis", {{"hysteresis.A", 0.5}, {"hysteresis.beta", 0.8}, {"hysteresis.gamma", 0.2}});
  InverseCompensator inverse(*m, "hysteresis", 0.0, 3.0, kTolerance);
  inverse.step(1.0);
  const double first = inverse.trial(2.0);
  inverse.trial(0.5);
  EXPECT_EQ(inverse.trial(2.0), first);
}

}  // namespace
}  // namespace hystbench
