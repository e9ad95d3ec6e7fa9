// The framework, not the plugin, counts, limits and records.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/core/evaluation_context.hpp"
#include "problems/functions/function_problem.hpp"

namespace hystbench {
namespace {

// Sphere that returns NaN where x[0] < 0 and +inf where x[0] > 4.
class PatchyProblem : public Problem {
 public:
  PatchyProblem() : sphere_("sphere", 2) {}
  std::string name() const override { return "patchy"; }
  const Bounds& bounds() const override { return sphere_.bounds(); }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const override {
    sphere_.evaluate(X, f);
    for (Eigen::Index i = 0; i < X.cols(); ++i) {
      if (X(0, i) < 0) f[i] = std::nan("");
      if (X(0, i) > 4) f[i] = HUGE_VAL;
    }
  }

 private:
  FunctionProblem sphere_;
};

Eigen::MatrixXd points(std::initializer_list<double> first) {
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(2, first.size());
  int i = 0;
  for (double v : first) X(0, i++) = v;
  return X;
}

TEST(EvaluationContext, NanAndInfBecomePlusInfinityAndNeverTheBest) {
  PatchyProblem problem;
  Budget budget;
  budget.evaluations = 100;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  ctx.evaluate(points({-1.0, 5.0, 3.0}), f);
  EXPECT_EQ(f[0], HUGE_VAL);
  EXPECT_EQ(f[1], HUGE_VAL);
  EXPECT_EQ(f[2], 9.0);
  EXPECT_EQ(ctx.best_value(), 9.0);
  EXPECT_EQ(ctx.best_point()[0], 3.0);
}

TEST(EvaluationContext, EvaluationBudgetTruncatesABatchAndIsNeverExceeded) {
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.evaluations = 5;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  EXPECT_EQ(ctx.evaluate(points({1, 2, 3}), f), 3);
  EXPECT_EQ(ctx.evaluate(points({0.5, 0.1, 0.2}), f), 2);  // only two left
  EXPECT_EQ(f[2], HUGE_VAL);
  EXPECT_EQ(ctx.evaluations(), 5);
  EXPECT_TRUE(ctx.stopped());
  EXPECT_EQ(ctx.stop_reason(), StopReason::Evaluations);
  EXPECT_EQ(ctx.evaluate(points({0.0}), f), 0);
  EXPECT_EQ(ctx.evaluations(), 5);
  EXPECT_DOUBLE_EQ(ctx.best_value(), 0.01);  // x = (0.1, 0): the point after the truncation was skipped
}

TEST(EvaluationContext, TraceRecordsEachImprovementWithItsEvaluationCount) {
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.evaluations = 10;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  ctx.evaluate(points({3, 4, 2, 5, 1}), f);
  ctx.finish();
  ASSERT_EQ(ctx.trace().size(), 3u);  // 9 at 1, 4 at 3, 1 at 5
  EXPECT_EQ(ctx.trace()[0].evaluations, 1);
  EXPECT_EQ(ctx.trace()[0].best, 9.0);
  EXPECT_EQ(ctx.trace()[1].evaluations, 3);
  EXPECT_EQ(ctx.trace()[2].evaluations, 5);
  EXPECT_EQ(ctx.trace()[2].best, 1.0);
  EXPECT_EQ(ctx.stop_reason(), StopReason::Converged);
}

TEST(EvaluationContext, IterationAndTargetBudgets) {
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.iterations = 3;
  budget.target = 0.5;
  EvaluationContext ctx(problem, budget, 1);
  int generations = 0;
  while (ctx.next_iteration()) ++generations;
  EXPECT_EQ(generations, 3);
  EXPECT_EQ(ctx.stop_reason(), StopReason::Iterations);

  EvaluationContext ctx2(problem, budget, 1);
  Eigen::VectorXd f;
  ctx2.evaluate(points({2.0, 0.5}), f);
  EXPECT_FALSE(ctx2.next_iteration());
  EXPECT_EQ(ctx2.stop_reason(), StopReason::Target);
}

TEST(EvaluationContext, RefusesPointsOutsideTheBounds) {
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.evaluations = 10;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  EXPECT_THROW(ctx.evaluate(points({1000.0}), f), std::logic_error);
}

TEST(EvaluationContext, ProgressIsTheUsedFractionOfTheBudget) {
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.evaluations = 8;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  ctx.evaluate(points({1, 2}), f);
  EXPECT_DOUBLE_EQ(ctx.progress(), 0.25);
}

TEST(EvaluationContext, ALimitedPhaseCountsItsProgressFromWhereItStarts) {
  // A polish cycle after the first runs a fresh optimizer: its schedules
  // must start at 0, not where the trial's evaluation count stands.
  FunctionProblem problem("sphere", 2);
  Budget budget;
  budget.evaluations = 100;
  EvaluationContext ctx(problem, budget, 1);
  Eigen::VectorXd f;
  ctx.evaluate(points({1, 2, 3, 4}), f);
  ctx.limit_evaluations(8);
  EXPECT_DOUBLE_EQ(ctx.progress(), 0.0);
  EXPECT_EQ(ctx.remaining_evaluations(), 8);
  ctx.evaluate(points({1, 2}), f);
  EXPECT_DOUBLE_EQ(ctx.progress(), 0.25);
  ctx.lift_evaluation_limit();
  EXPECT_DOUBLE_EQ(ctx.progress(), 0.06);
  EXPECT_EQ(ctx.remaining_evaluations(), 94);
}

}  // namespace
}  // namespace hystbench
