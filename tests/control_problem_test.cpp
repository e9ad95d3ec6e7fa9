// Controller tuning as a problem: log-scaled constants, one closed-loop run
// per candidate, divergence as +inf, bad keys named.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "problems/control/control_problem.hpp"

namespace hystbench {
namespace {

nlohmann::json spec() {
  return {{"type", "control"},
          {"experiment", "benchmarks/experiments/avc_beam.json"},
          {"controller", "fxnlms"},
          {"tune", {{{"param", "mu"}, {"lower", 1e-4}, {"upper", 1.0}, {"scale", "log"}}}},
          {"duration_s", 20}};
}

TEST(ControlProblem, LogScaledStepAndFitnessOfOneLoop) {
  const auto problem = make_problem(spec(), HYSTBENCH_SOURCE_DIR);
  EXPECT_EQ(problem->dimension(), 1);
  EXPECT_EQ(problem->bounds().names[0], "log10(mu)");
  EXPECT_DOUBLE_EQ(problem->bounds().lower[0], -4.0);
  EXPECT_DOUBLE_EQ(problem->bounds().upper[0], 0.0);
  const auto& control = dynamic_cast<const ControlProblem&>(*problem);
  Eigen::VectorXd x(1);
  x << std::log10(0.003);
  EXPECT_NEAR(control.params_of(x)["mu"].get<double>(), 0.003, 1e-15);
  // A good step: the error falls by more than 40 dB within a few seconds.
  const double good = control.fitness(x);
  EXPECT_GT(good, 0.0);
  EXPECT_LT(good, 0.02);
  // The same candidate gives the same fitness (fixed noise seed).
  EXPECT_EQ(control.fitness(x), good);
  // A step of 1 makes the loop diverge: +inf, not a crash.
  x << 0.0;
  EXPECT_TRUE(std::isinf(control.fitness(x)));
}

TEST(ControlProblem, BadTuneIsNamed) {
  auto s = spec();
  s["tune"][0]["param"] = "mu_typo";
  try {
    make_problem(s, HYSTBENCH_SOURCE_DIR);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("problem.tune[0]"), std::string::npos) << e.what();
  }
  s = spec();
  s["tune"][0]["lower"] = 0.0;
  try {
    make_problem(s, HYSTBENCH_SOURCE_DIR);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scale log"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hystbench
