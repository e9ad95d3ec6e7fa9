// Controllers: the FxLMS update by hand, and every step rule against steps
// computed by hand on a short constructed error sequence.
#include <gtest/gtest.h>

#include <vector>

#include "framework/control/controller.hpp"
#include "framework/core/error.hpp"

namespace hystbench {
namespace {

std::unique_ptr<Controller> make(const std::string& name, const nlohmann::json& params) {
  const ControllerInfo& info = ControllerRegistry::instance().find(name, "test");
  return info.create(validate_params(info.params, params, "test"));
}

// Steps used at each adaptation when the errors are `errors` (x = x' = 0).
std::vector<double> steps(Controller& c, const std::vector<double>& errors) {
  std::vector<double> out;
  c.reset();
  for (double e : errors) {
    c.output(0.0);
    c.adapt(e, 0.0);
    out.push_back(c.step_size());
  }
  return out;
}

void expect_steps(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "sample " << i;
}

TEST(Controllers, AllSixAreRegisteredWithCitations) {
  for (const char* name : {"off", "fxlms", "fxnlms", "vss_fxlms", "vss_kwong", "vss_aboulnasr"}) {
    const ControllerInfo& info = ControllerRegistry::instance().find(name, "test");
    if (std::string(name) != "off") {
      EXPECT_FALSE(info.citation.empty()) << name;
    }
  }
  EXPECT_TRUE(ControllerRegistry::instance().find("vss_fxlms", "t").reconstructed);
  EXPECT_FALSE(ControllerRegistry::instance().find("fxnlms", "t").reconstructed);
}

TEST(Controllers, FxlmsUpdateAndOutputLimitByHand) {
  auto c = make("fxlms", {{"taps", 2}, {"mu", 0.5}, {"output_limit", 2.0}});
  c->reset();
  EXPECT_EQ(c->output(1.0), 0.0);
  c->adapt(1.0, 2.0);                  // w = -0.5 * 1 * [2, 0] = [-1, 0]
  EXPECT_DOUBLE_EQ(c->weight_norm(), 1.0);
  EXPECT_DOUBLE_EQ(c->output(1.5), -1.5);  // x_vec = [1.5, 1]
  c->adapt(-1.0, 1.0);                 // x'_vec = [1, 2]: w = [-1, 0] + 0.5 [1, 2] = [-0.5, 1]
  EXPECT_DOUBLE_EQ(c->output(4.0), -0.5);  // x_vec = [4, 1.5]: -2 + 1.5
  EXPECT_DOUBLE_EQ(c->output(-6.0), 2.0);  // x_vec = [-6, 4]: 3 + 4 = 7, clipped to 2
}

TEST(Controllers, NormalisedStepDividesByFilteredPower) {
  auto c = make("fxnlms", {{"taps", 2}, {"mu", 0.5}, {"delta", 0.0}});
  c->reset();
  c->output(1.0);
  c->adapt(1.0, 2.0);  // w = -0.5 / 4 * 1 * [2, 0] = [-0.25, 0]
  EXPECT_DOUBLE_EQ(c->output(2.0), -0.5);
}

TEST(Controllers, LeakageShrinksTheWeights) {
  auto c = make("fxlms", {{"taps", 1}, {"mu", 0.5}, {"leakage", 0.2}});
  c->reset();
  c->output(0.0);
  c->adapt(1.0, 1.0);  // w = -0.5
  c->output(0.0);
  c->adapt(0.0, 0.0);  // w = (1 - 0.5 * 0.2) (-0.5) = -0.45
  EXPECT_DOUBLE_EQ(c->weight_norm(), 0.45);
}

TEST(StepRules, FixedStepsStayFixed) {
  expect_steps(steps(*make("fxnlms", {{"mu", 0.01}}), {1, 2, 3}), {0.01, 0.01, 0.01});
  expect_steps(steps(*make("off", nlohmann::json::object()), {1, 2}), {0, 0});
}

// mu(n+1) = clip(alpha mu(n) + gamma e(n)^2): used 1, then 0.5 + 0.1 = 0.6,
// 0.3 + 0.4 = 0.7, 0.35 + 0 = 0.35.
TEST(StepRules, KwongByHand) {
  auto c = make("vss_kwong", {{"alpha", 0.5}, {"gamma", 0.1}, {"mu_min", 0.01}, {"mu_max", 1.0}});
  expect_steps(steps(*c, {1, 2, 0, 0.5}), {1.0, 0.6, 0.7, 0.35});
}

// p(n) = 0.5 p(n-1) + 0.5 e(n) e(n-1): 0, 1, 0.5, 0.25; mu: used 1, then
// 0.5 + 0 = 0.5, 0.25 + 1 -> 1 (clipped), 0.5 + 0.25 = 0.75.
TEST(StepRules, AboulnasrByHand) {
  auto c = make("vss_aboulnasr",
                {{"alpha", 0.5}, {"gamma", 1.0}, {"beta", 0.5}, {"mu_min", 0.01}, {"mu_max", 1.0}});
  expect_steps(steps(*c, {1, 2, 0, 0.5}), {1.0, 0.5, 1.0, 0.75});
}

// P(n) = 0.5 P(n-1) + 0.5 e(n)^2: 0.5, 0.75, 0.375, 0.1875, 2.09375; with M = 2,
// rho = 0, 0, 0.25, 0.75, 4.58333; mu(0) = 1, then 0.5, 0.275, 0.2125, 0.5645833.
TEST(StepRules, NormalisedErrorChangeByHand) {
  auto c = make("vss_fxlms", {{"lambda", 0.5}, {"window", 2}, {"alpha", 0.5}, {"gamma", 0.1},
                              {"delta_p", 1e-300}, {"mu_min", 0.01}, {"mu_max", 1.0}});
  expect_steps(steps(*c, {1, 1, 0, 0, 2}), {1.0, 0.5, 0.275, 0.2125, 0.10625 + 0.1 * 1.71875 / 0.375});
  // reset() starts the rule again.
  expect_steps(steps(*c, {1, 1}), {1.0, 0.5});
}

TEST(StepRules, StepBoundsOutOfOrderAreAnInputError) {
  try {
    make("vss_kwong", {{"mu_min", 0.1}, {"mu_max", 0.01}});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mu_min"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hystbench
