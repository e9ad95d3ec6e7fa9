// The batched Hammerstein kernel against the scalar reference.
//
// Both perform the same floating-point operations in the same order on each
// candidate (contraction into fused multiply-adds is off), so every value
// must be bit-identical: EXPECT_EQ on doubles, not a tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "framework/core/rng.hpp"
#include "framework/io/measurement.hpp"
#include "problems/hammerstein/batched_sse.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace hystbench {
namespace {

EvaluationOptions on_threads(int threads) {
  EvaluationOptions o;
  o.threads = threads;
  return o;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

const Measurement& data() {
  static const Measurement m =
      read_measurement(std::string(HYSTBENCH_SOURCE_DIR) + "/problems/hammerstein/data/default.csv", {});
  return m;
}

// The parameters the default data was simulated from.
Eigen::VectorXd truth() {
  return HammersteinParams{0.4, 0.0015, 0.0005, 0.2, 0.15, 6e-05, 1.583e-05, 0.001194, 1.0, 0.2, 0.09, -1.0, 0.29}
      .to_vector();
}

// Uniform in the default search box: about half of these have an unstable
// linear block, and some diverge in the paper form.
Eigen::MatrixXd uniform_candidates(Eigen::Index n, std::uint64_t seed) {
  const Bounds b = HammersteinProblem::default_bounds();
  Rng rng(seed);
  Eigen::MatrixXd X(b.dimension(), n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int j = 0; j < b.dimension(); ++j) X(j, i) = rng.uniform(b.lower[j], b.upper[j]);
  return X;
}

// Within +-10 % of the truth: stable, finite, and each one different.
Eigen::MatrixXd near_truth(Eigen::Index n, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXd X(HammersteinParams::kCount, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int j = 0; j < HammersteinParams::kCount; ++j) X(j, i) = truth()[j] * rng.uniform(0.9, 1.1);
  return X;
}

Eigen::VectorXd scalar(const Eigen::MatrixXd& X, BoucWenForm form) {
  Eigen::VectorXd f(X.cols());
  for (Eigen::Index i = 0; i < X.cols(); ++i)
    f[i] = hammerstein_sse(HammersteinParams::from_vector(X.col(i)), data().u, data().y, data().sample_time, form);
  return f;
}

Eigen::VectorXd batched(const Eigen::MatrixXd& X, BoucWenForm form, int threads = 1) {
  Eigen::VectorXd f(X.cols());
  hammerstein_sse_batched(X, data().u, data().y, data().sample_time, form, f, on_threads(threads));
  return f;
}

void expect_identical(const Eigen::VectorXd& expected, const Eigen::VectorXd& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (Eigen::Index i = 0; i < expected.size(); ++i) EXPECT_EQ(expected[i], actual[i]) << "candidate " << i;
}

class BatchedSse : public testing::TestWithParam<BoucWenForm> {};

TEST_P(BatchedSse, UniformCandidatesInTheBoundsEqualTheScalarPath) {
  const Eigen::MatrixXd X = uniform_candidates(64, 7);
  const Eigen::VectorXd expected = scalar(X, GetParam());
  EXPECT_GT((expected.array() == kInf).count(), 0);  // the mix includes unstable candidates
  EXPECT_GT((expected.array() < kInf).count(), 0);
  expect_identical(expected, batched(X, GetParam()));
}

TEST_P(BatchedSse, CandidatesNearTheTruthEqualTheScalarPath) {
  const Eigen::MatrixXd X = near_truth(40, 3);
  const Eigen::VectorXd expected = scalar(X, GetParam());
  if (GetParam() == BoucWenForm::Increment) {
    EXPECT_TRUE(expected.allFinite());
  }
  expect_identical(expected, batched(X, GetParam()));
}

TEST_P(BatchedSse, PartialBlocksAreEvaluatedAndPaddingIsDiscarded) {
  // Around one and two blocks of the native width, and a lone candidate.
  const int w = batched_sse_lanes();
  for (const Eigen::Index n : {Eigen::Index(1), Eigen::Index(3), Eigen::Index(w), Eigen::Index(w + 1),
                               Eigen::Index(2 * w + 1), Eigen::Index(8), Eigen::Index(9), Eigen::Index(17)}) {
    SCOPED_TRACE(n);
    const Eigen::MatrixXd X = near_truth(n, 100 + n);
    expect_identical(scalar(X, GetParam()), batched(X, GetParam()));
  }
}

TEST_P(BatchedSse, UnstableCandidateGivesInfWithoutPoisoningItsBlock) {
  Eigen::MatrixXd X = near_truth(9, 5);
  X(12, 2) = 1.5;   // ARX denominator z^2 + c z + d with d > 1: unstable
  X(11, 6) = 2.0;   // c = 2 with d = 0.29: a root outside the unit circle
  X(6, 4) = 0.0;    // M = D = 0 leaves a real root at -1: marginal, not stable
  X(7, 4) = 0.0;
  const Eigen::VectorXd expected = scalar(X, GetParam());
  ASSERT_EQ(expected[2], kInf);
  ASSERT_EQ(expected[6], kInf);
  ASSERT_EQ(expected[4], kInf);
  const Eigen::VectorXd f = batched(X, GetParam());
  expect_identical(expected, f);
  if (GetParam() == BoucWenForm::Increment) {
    for (const int i : {0, 1, 3, 5, 7, 8}) EXPECT_LT(f[i], kInf) << "candidate " << i;
  }
}

TEST_P(BatchedSse, DivergingBoucWenStateGivesInfWithoutPoisoningItsBlock) {
  // Stable linear blocks, but beta, gamma < 0 make the hysteresis state grow
  // without bound: the SSE overflows, and must read +inf, never NaN.
  Eigen::MatrixXd X = near_truth(8, 9);
  X(1, 3) = -0.5;
  X(2, 3) = -0.5;
  const Eigen::VectorXd expected = scalar(X, GetParam());
  ASSERT_EQ(expected[3], kInf);
  const Eigen::VectorXd f = batched(X, GetParam());
  expect_identical(expected, f);
}

TEST_P(BatchedSse, ValuesDoNotDependOnTheThreadCount) {
  const Eigen::MatrixXd X = uniform_candidates(70, 11);
  expect_identical(batched(X, GetParam(), 1), batched(X, GetParam(), 2));
}

TEST_P(BatchedSse, ProblemEvaluateUsesTheBatchedKernelWithAnyThreadCount) {
  const HammersteinProblem problem(data(), GetParam(), HammersteinProblem::default_bounds());
  Eigen::MatrixXd X(HammersteinParams::kCount, 50);
  X << uniform_candidates(25, 13), near_truth(25, 17);
  const Eigen::VectorXd expected = scalar(X, GetParam());
  Eigen::VectorXd one(X.cols()), two(X.cols()), plain(X.cols());
  problem.evaluate_with(X, one, on_threads(1));
  problem.evaluate_with(X, two, on_threads(2));
  problem.evaluate(X, plain);
  expect_identical(expected, one);
  expect_identical(expected, two);
  expect_identical(expected, plain);
}

INSTANTIATE_TEST_SUITE_P(Forms, BatchedSse, testing::Values(BoucWenForm::Increment, BoucWenForm::Paper),
                         [](const auto& info) { return to_string(info.param); });

}  // namespace
}  // namespace hystbench
