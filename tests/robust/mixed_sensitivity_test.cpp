// The mixed-sensitivity plant against Skogestad & Postlethwaite's Example
// 2.11 (Multivariable Feedback Control, 2nd ed.): G = 200/((10s+1)(0.05s+1)²),
// Wp = (s/M + wb)/(s + wb A) with M = 1.5, wb = 10, A = 1e-4, Wu = 1; the
// optimal γ is 1.37 (1.3659 to four digits), which python-control's test
// also asserts. And the plant's outputs hand-checked on a static example.
#include <gtest/gtest.h>

#include "framework/core/error.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/hinf_synthesis.hpp"
#include "framework/robust/mixed_sensitivity.hpp"
#include "tests/robust/slicot_examples.hpp"

namespace hystbench::robust {
namespace {

using examples::rows;

StateSpace gain(double k) {
  return {Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 1), Eigen::MatrixXd(1, 0), Eigen::MatrixXd::Constant(1, 1, k)};
}

TEST(MixedSensitivity, SkogestadPostlethwaiteExample211) {
  // 200/((10s+1)(0.05s+1)^2) = 8000/(s^3 + 40.1 s^2 + 404 s + 40), companion form.
  const StateSpace G{rows(3, 3, {0, 1, 0, 0, 0, 1, -40, -404, -40.1}), rows(3, 1, {0, 0, 1}),
                     rows(1, 3, {8000, 0, 0}), Eigen::MatrixXd::Zero(1, 1)};
  const double M = 1.5, wb = 10, A = 1e-4;  // Wp = 1/M + (wb - wb A/M)/(s + wb A)
  const StateSpace Wp{Eigen::MatrixXd::Constant(1, 1, -wb * A), Eigen::MatrixXd::Ones(1, 1),
                      Eigen::MatrixXd::Constant(1, 1, wb - wb * A / M), Eigen::MatrixXd::Constant(1, 1, 1 / M)};
  const StateSpace P = mixed_sensitivity_plant(G, {Wp, gain(1.0), std::nullopt});
  ASSERT_EQ(P.states(), 4);
  ASSERT_EQ(P.inputs(), 2);
  ASSERT_EQ(P.outputs(), 3);
  const HinfController k = hinf_synthesis(P, 1, 1);
  EXPECT_NEAR(k.gamma_min, 1.3659, 0.01 * 1.3659);
  EXPECT_LE(hinf_norm(k.closed_loop, TimeDomain::Continuous).norm, k.gamma * (1 + 1e-6));
}

TEST(MixedSensitivity, StaticPlantGivesTheHandComputedMap) {
  // G = 2, W1 = 3, W2 = 5, W3 = 7: from [w; u], z1 = 3(w - 2u), z2 = 5u, z3 = 14u, v = w - 2u.
  const StateSpace P = mixed_sensitivity_plant(gain(2.0), {gain(3.0), gain(5.0), gain(7.0)});
  EXPECT_EQ(P.states(), 0);
  EXPECT_LT((P.D - rows(4, 2, {3, -6, 0, 5, 0, 14, 1, -2})).norm(), 1e-15) << P.D;
}

TEST(MixedSensitivity, WeightOfTheWrongSizeIsNamed) {
  const StateSpace two_inputs{Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 2), Eigen::MatrixXd(1, 0),
                              Eigen::MatrixXd::Ones(1, 2)};
  try {
    mixed_sensitivity_plant(gain(2.0), {two_inputs, std::nullopt, std::nullopt});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("W1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(mixed_sensitivity_plant(gain(2.0), {}), InputError);
}

}  // namespace
}  // namespace hystbench::robust
