// Model reduction and the bilinear map against SLICOT's published examples:
// AB09AD's and AB09HD's 7-state system reduced to 5 states, with their
// Hankel singular values and the error each method guarantees, and
// AB04MD's 2-state example, whose result is a formula.
#include <gtest/gtest.h>

#include <vector>

#include "framework/core/error.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/model_reduction.hpp"
#include "framework/robust/tustin.hpp"
#include "tests/robust/slicot_examples.hpp"

namespace hystbench::robust {
namespace {

using examples::rows;
StateSpace ab09_example() { return examples::ab09_system(); }


void expect_values(const std::vector<double>& got, const std::vector<double>& published) {
  ASSERT_EQ(got.size(), published.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], published[i], 1e-4) << i;
}

TEST(BalancedTruncation, ReproducesSlicotsExampleAndKeepsItsBound) {
  const StateSpace g = ab09_example();
  const Reduction r = balanced_truncation(g, TimeDomain::Continuous, 5);
  EXPECT_EQ(r.reduced.states(), 5);
  expect_values(r.hankel, {2.5139, 2.0846, 1.9178, 0.7666, 0.5473, 0.0253, 0.0246});
  EXPECT_NEAR(r.error_bound, 2 * (r.hankel[5] + r.hankel[6]), 1e-12);
  const double error = hinf_norm(difference(g, r.reduced), TimeDomain::Continuous).norm;
  EXPECT_LE(error, r.error_bound);
  EXPECT_GE(error, r.hankel[5] * (1 - 1e-6));  // no reduction beats the first discarded value
}

TEST(StochasticTruncation, ReproducesSlicotsHankelValues) {
  const Reduction r = stochastic_truncation(ab09_example(), TimeDomain::Continuous, 5, 1.0);
  EXPECT_EQ(r.reduced.states(), 5);
  EXPECT_EQ(r.unstable_kept, 0);
  expect_values(r.hankel, {0.8803, 0.8506, 0.8038, 0.4494, 0.3973, 0.0214, 0.0209});
  EXPECT_NEAR(r.error_bound, (1.0214 / 0.9786) * (1.0209 / 0.9791) - 1, 1e-3);
}

TEST(BalancedTruncation, OrderZeroAndMismatchedDifferenceAreRefused) {
  EXPECT_THROW(balanced_truncation(ab09_example(), TimeDomain::Continuous, 0), InputError);
  EXPECT_THROW(stochastic_truncation(ab09_example(), TimeDomain::Continuous, 0, 1.0), InputError);
  const StateSpace one{Eigen::MatrixXd::Constant(1, 1, -1.0), Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1),
                       Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_THROW(difference(ab09_example(), one), InputError);
}

TEST(StochasticTruncation, StrictlyProperSystemNeedsBeta) {
  try {
    stochastic_truncation(ab09_example(), TimeDomain::Continuous, 5, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("beta"), std::string::npos) << e.what();
  }
}

TEST(BalancedTruncation, UnstableSystemIsNamed) {
  StateSpace g = ab09_example();
  g.A(0, 0) = 5.0;
  try {
    balanced_truncation(g, TimeDomain::Continuous, 5);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not stable"), std::string::npos) << e.what();
  }
}

TEST(Tustin, ReproducesSlicotsExampleAndInvertsIt) {
  // AB04MD's example is at alpha = beta = 1, that is Ts = 2.
  const StateSpace c{rows(2, 2, {1, 0.5, 0.5, 1}), rows(2, 2, {0, 1, -1, 0}), rows(2, 2, {-1, 0, 0, 1}),
                     rows(2, 2, {1, 0, 0, -1})};
  const StateSpace d = tustin(c, 2.0);
  const double r = 2.0 * std::sqrt(2.0);
  EXPECT_LT((d.A - rows(2, 2, {-1, -4, -4, -1})).norm(), 1e-12);
  EXPECT_LT((d.B - rows(2, 2, {r, 0, 0, -r})).norm(), 1e-12);
  EXPECT_LT((d.C - rows(2, 2, {0, r, -r, 0})).norm(), 1e-12);
  EXPECT_LT((d.D - rows(2, 2, {-1, 0, 0, -3})).norm(), 1e-12);
  const StateSpace back = inverse_tustin(d, 2.0);
  EXPECT_LT((back.A - c.A).norm(), 1e-12);
  EXPECT_LT((back.D - c.D).norm(), 1e-12);
}

TEST(Tustin, PoleAtTwoOverTsIsNamed) {
  const StateSpace c{Eigen::MatrixXd::Constant(1, 1, 2.0), Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1),
                     Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_THROW(tustin(c, 1.0), InputError);
  EXPECT_THROW(tustin(c, 0.0), InputError);
}

}  // namespace
}  // namespace hystbench::robust
