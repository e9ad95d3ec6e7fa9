// Early abandonment: a candidate that certainly loses against its threshold
// may stop early, and nothing an optimizer or a report sees changes.
#include <gtest/gtest.h>

#include "framework/core/evaluation_context.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/rng.hpp"
#include "framework/io/measurement.hpp"
#include "problems/hammerstein/batched_sse.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace hystbench {
namespace {

const Measurement& data() {
  static const Measurement m =
      read_measurement(std::string(HYSTBENCH_SOURCE_DIR) + "/problems/hammerstein/data/default.csv", {});
  return m;
}

// Within +-10 % of the parameters the default data was simulated from.
Eigen::MatrixXd near_truth(Eigen::Index n, std::uint64_t seed) {
  const Eigen::VectorXd x0 =
      HammersteinParams{0.4, 0.0015, 0.0005, 0.2, 0.15, 6e-05, 1.583e-05, 0.001194, 1.0, 0.2, 0.09, -1.0, 0.29}
          .to_vector();
  Rng rng(seed);
  Eigen::MatrixXd X(x0.size(), n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < x0.size(); ++j) X(j, i) = x0[j] * rng.uniform(0.9, 1.1);
  return X;
}

Eigen::VectorXd batched(const Eigen::MatrixXd& X, const Eigen::VectorXd& limit) {
  Eigen::VectorXd f(X.cols());
  EvaluationOptions options;
  if (limit.size() > 0) options.abandon_above = std::span<const double>(limit.data(), limit.size());
  hammerstein_sse_batched(X, data().u, data().y, data().sample_time, BoucWenForm::Increment, f, options);
  return f;
}

TEST(EarlyAbandonment, WinnersAndTiesKeepTheirExactValue) {
  const Eigen::MatrixXd X = near_truth(20, 1);
  const Eigen::VectorXd exact = batched(X, {});
  Eigen::VectorXd limit = exact;      // a tie must not be abandoned ("<=" selection)
  limit.head(10) *= 2.0;              // winners
  const Eigen::VectorXd f = batched(X, limit);
  for (Eigen::Index i = 0; i < X.cols(); ++i) EXPECT_EQ(f[i], exact[i]) << "candidate " << i;
}

TEST(EarlyAbandonment, LosersStopEarlyWithAValueAboveTheirLimit) {
  const Eigen::MatrixXd X = near_truth(19, 2);  // two full blocks of 8 and a partial one
  const Eigen::VectorXd exact = batched(X, {});
  const Eigen::VectorXd limit = 0.01 * exact;
  const Eigen::VectorXd f = batched(X, limit);
  for (Eigen::Index i = 0; i < X.cols(); ++i) {
    EXPECT_GT(f[i], limit[i]) << "candidate " << i;
    EXPECT_LE(f[i], exact[i]) << "candidate " << i;  // a partial sum of the same squares
  }
  EXPECT_LT(f.sum(), 0.5 * exact.sum());  // they did stop early
}

TEST(EarlyAbandonment, ALoserBesideAWinnerIsStillCorrect) {
  const Eigen::MatrixXd X = near_truth(16, 3);
  const Eigen::VectorXd exact = batched(X, {});
  Eigen::VectorXd limit = 0.01 * exact;
  limit[5] = exact[5];  // one winner keeps its block running to the end
  const Eigen::VectorXd f = batched(X, limit);
  EXPECT_EQ(f[5], exact[5]);
  for (Eigen::Index i = 0; i < X.cols(); ++i) EXPECT_GT(f[i], limit[i] * (i == 5 ? 0.5 : 1.0));
}

TEST(EarlyAbandonment, ContextNeverLetsAnAbandonedValueBecomeTheBest) {
  const HammersteinProblem problem(data(), BoucWenForm::Increment, HammersteinProblem::default_bounds());
  Budget budget;
  EvaluationContext ctx(problem, budget, 1);
  const Eigen::MatrixXd X = near_truth(9, 4);
  Eigen::VectorXd f;
  ctx.evaluate(Eigen::MatrixXd(X.col(0)), f);
  const double best = ctx.best_value();
  // Thresholds of 0 would abandon everything at once; the context raises
  // them to the best-so-far, so only candidates worse than it may stop.
  ctx.evaluate_against(X.rightCols(8), Eigen::VectorXd::Zero(8), f);
  Eigen::VectorXd exact(8);
  problem.evaluate(X.rightCols(8), exact);
  for (Eigen::Index i = 0; i < 8; ++i) {
    if (exact[i] <= best) EXPECT_EQ(f[i], exact[i]);
    else EXPECT_GT(f[i], best);
  }
  EXPECT_EQ(ctx.best_value(), std::min(best, exact.minCoeff()));
}

// Whole DE runs on the Hammerstein problem: the same survivors, best point,
// trace and evaluation count with and without abandonment.
class EarlyAbandonmentDe : public testing::TestWithParam<const char*> {};

TEST_P(EarlyAbandonmentDe, RunsAreIdenticalWithAndWithoutIt) {
  const HammersteinProblem problem(data(), BoucWenForm::Increment, HammersteinProblem::default_bounds());
  Budget budget;
  budget.evaluations = 1200;
  const auto run = [&](bool abandon) {
    EvaluationContext ctx(problem, budget, 77);
    ctx.set_early_abandonment(abandon);
    const auto& info = OptimizerRegistry::instance().find(GetParam(), "algorithm");
    info.create(validate_params(info.params, {{"np", 24}}, "test"))->run(ctx);
    return ctx;
  };
  const EvaluationContext with = run(true), without = run(false);
  EXPECT_EQ(with.best_value(), without.best_value());
  EXPECT_EQ(with.best_point(), without.best_point());
  EXPECT_EQ(with.evaluations(), without.evaluations());
  ASSERT_EQ(with.trace().size(), without.trace().size());
  for (std::size_t i = 0; i < with.trace().size(); ++i) {
    EXPECT_EQ(with.trace()[i].evaluations, without.trace()[i].evaluations);
    EXPECT_EQ(with.trace()[i].best, without.trace()[i].best);
  }
}

INSTANTIATE_TEST_SUITE_P(Plugins, EarlyAbandonmentDe, testing::Values("de", "amfmmde", "mede"));

}  // namespace
}  // namespace hystbench
