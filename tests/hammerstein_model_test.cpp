// The seed model against values computed by hand from
// docs/models.md#hammerstein-seed-model.
#include <gtest/gtest.h>

#include <cmath>

#include "problems/hammerstein/hammerstein_model.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace hystbench {
namespace {

// alpha L = 1, Ts = 0.1, M = 1, D = 2, K = 50:
// e1 = 4M + 2D Ts + K Ts^2 = 4.9, f1 = 2K Ts^2 - 8M = -7, g1 = 4M - 2D Ts + K Ts^2 = 4.1.
const HammersteinParams kParams{0.5, 0.2, 0.1, 2.0, 0.8, 0.3, 1.0, 2.0, 50.0, 0.5, 0.25, -0.3, 0.1};
const double kTs = 0.1;

Eigen::VectorXd input() {
  Eigen::VectorXd u(5);
  u << 1.0, 3.0, 2.0, -1.0, 0.5;
  return u;
}

TEST(HammersteinModel, IncrementFormMatchesHandComputation) {
  // k = 0: du = 1, h = 1, h1 = 0.8 + 0.3 - 1 = 0.1, r = Ts^2 h1 / e1 = 0.001/4.9, y = 0.
  // k = 1: du = 2, h = 1 + 2 - 0.2*2*1 - 0.1*2*1 = 2.4, y = a r[0] = 0.5 * 0.001/4.9.
  // Later samples by the same recurrence, in double precision.
  const Eigen::VectorXd y = simulate_hammerstein(kParams, input(), kTs, BoucWenForm::Increment);
  ASSERT_EQ(y.size(), 5);
  EXPECT_EQ(y[0], 0.0);
  EXPECT_NEAR(y[1], 0.5 * 0.001 / 4.9, 1e-18);
  EXPECT_NEAR(y[2], 0.0031865889212827994, 1e-15);
  EXPECT_NEAR(y[3], 0.01413423573511037, 1e-15);
  EXPECT_NEAR(y[4], 0.031588905218063894, 1e-15);
}

TEST(HammersteinModel, PaperFormDrivesBoucWenWithTheInputItself) {
  // k = 1: drive = u = 3, h = 1 + 3 - 0.2*3*1 - 0.1*3*1 = 3.1 (the increment form gives 2.4).
  const Eigen::VectorXd y = simulate_hammerstein(kParams, input(), kTs, BoucWenForm::Paper);
  EXPECT_EQ(y[0], 0.0);
  EXPECT_NEAR(y[1], 0.5 * 0.001 / 4.9, 1e-18);
  EXPECT_NEAR(y[2], 0.0024723032069970852, 1e-15);
  EXPECT_NEAR(y[3], 0.0089913785922532286, 1e-15);
  EXPECT_NEAR(y[4], 0.012751878978996848, 1e-15);
}

TEST(HammersteinModel, PaperFormIsNoHysteresisForPositiveInput) {
  // For u >= 0 the literal form relaxes to alpha L / (beta + gamma) whatever u is.
  HammersteinParams p = kParams;
  p.beta = 0.3;
  p.gamma = 0.2;
  Eigen::VectorXd u = Eigen::VectorXd::Constant(400, 0.7);
  for (int k = 200; k < 400; ++k) u[k] = 1.9;  // another level, same limit
  double h = 0.0;
  for (int k = 0; k < 400; ++k) h = h + p.alpha * p.L * u[k] - p.beta * u[k] * h - p.gamma * u[k] * std::abs(h);
  EXPECT_NEAR(h, p.alpha * p.L / (p.beta + p.gamma), 1e-9);
}

TEST(HammersteinModel, SseIsSumOfSquaredErrors) {
  const Eigen::VectorXd u = input();
  const Eigen::VectorXd y_model = simulate_hammerstein(kParams, u, kTs, BoucWenForm::Increment);
  Eigen::VectorXd y = y_model;
  y[2] += 0.5;
  y[4] -= 2.0;
  EXPECT_NEAR(hammerstein_sse(kParams, u, y, kTs, BoucWenForm::Increment), 0.25 + 4.0, 1e-12);
}

TEST(HammersteinModel, UnstableArxGivesInfinityNotNan) {
  HammersteinParams p = kParams;
  p.c = -2.5;  // ARX pole outside the unit circle
  p.d = 1.5;
  EXPECT_FALSE(linear_blocks_stable(p, kTs));
  const double f = hammerstein_sse(p, input(), input(), kTs, BoucWenForm::Increment);
  EXPECT_TRUE(std::isinf(f) && f > 0);
}

TEST(HammersteinModel, NegativeDampingIsUnstable) {
  HammersteinParams p = kParams;
  p.D = -2.0;
  EXPECT_FALSE(linear_blocks_stable(p, kTs));
  EXPECT_EQ(hammerstein_sse(p, input(), input(), kTs, BoucWenForm::Increment),
            std::numeric_limits<double>::infinity());
}

TEST(HammersteinModel, DivergingBoucWenGivesInfinity) {
  // Literal form with (beta + gamma) u > 2 oscillates with growing amplitude.
  HammersteinParams p = kParams;
  p.beta = 3.0;  // h -> -2.5 h + 1 or -1.5 h + 1 each step: grows without bound
  p.gamma = 0.5;
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(5000, 1.0);
  const double f = hammerstein_sse(p, u, Eigen::VectorXd::Zero(5000), kTs, BoucWenForm::Paper);
  EXPECT_EQ(f, std::numeric_limits<double>::infinity());
}

TEST(HammersteinModel, HalfOfTheDefaultBoxIsUnstableYetNeverNan) {
  const Bounds b = HammersteinProblem::default_bounds();
  Eigen::VectorXd u(2000);
  for (int k = 0; k < 2000; ++k) u[k] = 375 + 625 * std::sin(0.02 * k);
  const Eigen::VectorXd y = Eigen::VectorXd::Zero(2000);
  int infinite = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd x(13);
    for (int j = 0; j < 13; ++j)  // low-discrepancy sweep of the box
      x[j] = b.lower[j] + std::fmod(0.5 + (i + 1) * std::sqrt(2.0 + j), 1.0) * (b.upper[j] - b.lower[j]);
    const double f = hammerstein_sse(HammersteinParams::from_vector(x), u, y, 1e-3, BoucWenForm::Increment);
    ASSERT_FALSE(std::isnan(f));
    infinite += std::isinf(f);
  }
  EXPECT_GT(infinite, n / 4);
  EXPECT_LT(infinite, 3 * n / 4);
}

}  // namespace
}  // namespace hystbench
