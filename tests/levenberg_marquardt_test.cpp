// Levenberg-Marquardt polish: converges on least-squares problems with a
// known optimum, spends exactly the evaluations it is given, and the
// Hammerstein residuals are the ones its SSE sums.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/core/evaluation_context.hpp"
#include "framework/io/measurement.hpp"
#include "framework/local/levenberg_marquardt.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace hystbench {
namespace {

// Rosenbrock as residuals: r = (10 (x2 - x1^2), 1 - x1), minimum 0 at (1, 1).
// Points with x1 > 1.9 "diverge" (+inf), as unstable models do.
class RosenbrockResiduals : public Problem, public LeastSquaresProblem {
 public:
  RosenbrockResiduals() {
    bounds_.lower = Eigen::Vector2d(-2, -2);
    bounds_.upper = Eigen::Vector2d(2, 2);
    bounds_.names = {"x1", "x2"};
  }
  std::string name() const override { return "rosenbrock residuals"; }
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const override {
    Eigen::VectorXd r(2);
    for (Eigen::Index i = 0; i < X.cols(); ++i) {
      residuals(X.col(i), r);
      f[i] = X(0, i) > 1.9 ? INFINITY : r.squaredNorm();
    }
  }
  Eigen::Index residual_count() const override { return 2; }
  void residuals(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> r) const override {
    r << 10 * (x[1] - x[0] * x[0]), 1 - x[0];
  }

 private:
  Bounds bounds_;
};

Budget evaluations(long n) {
  Budget b;
  b.evaluations = n;
  return b;
}

TEST(LevenbergMarquardt, ReachesTheRosenbrockMinimumFromTheClassicStart) {
  RosenbrockResiduals problem;
  EvaluationContext ctx(problem, evaluations(1000), 1);
  const std::string why = run_levenberg_marquardt(ctx, problem, Eigen::Vector2d(-1.2, 1.0), 1000);
  EXPECT_EQ(why, "converged");
  EXPECT_LT(ctx.best_value(), 1e-20);
  EXPECT_NEAR(ctx.best_point()[0], 1.0, 1e-9);
  EXPECT_NEAR(ctx.best_point()[1], 1.0, 1e-9);
  // Each iteration costs a Jacobian (2 evaluations) and a step: far fewer
  // than the thousands a derivative-free method needs here.
  EXPECT_LT(ctx.evaluations(), 200);
}

TEST(LevenbergMarquardt, SpendsExactlyTheEvaluationsItIsGiven) {
  RosenbrockResiduals problem;
  EvaluationContext ctx(problem, evaluations(1000), 1);
  EXPECT_EQ(run_levenberg_marquardt(ctx, problem, Eigen::Vector2d(-1.2, 1.0), 7), "budget");
  EXPECT_EQ(ctx.evaluations(), 7);
  // ... and never more than the trial's budget.
  EvaluationContext small(problem, evaluations(5), 1);
  EXPECT_EQ(run_levenberg_marquardt(small, problem, Eigen::Vector2d(-1.2, 1.0), 1000), "budget");
  EXPECT_EQ(small.evaluations(), 5);
}

TEST(LevenbergMarquardt, StepsBackFromDivergingCandidatesAndStaysInTheBox) {
  RosenbrockResiduals problem;
  EvaluationContext ctx(problem, evaluations(2000), 1);
  // From next to the diverging region (x1 > 1.9), where the first steps
  // would cross it.
  run_levenberg_marquardt(ctx, problem, Eigen::Vector2d(1.85, -1.5), 2000);
  EXPECT_LT(ctx.best_value(), 1e-12);
  EXPECT_TRUE(problem.bounds().contains(ctx.best_point()));
}

TEST(LevenbergMarquardt, GivesTheSameTraceWhateverTheTrialSeed) {
  RosenbrockResiduals problem;
  EvaluationContext a(problem, evaluations(1000), 1), b(problem, evaluations(1000), 2);
  run_levenberg_marquardt(a, problem, Eigen::Vector2d(0.3, -1.0), 1000);
  run_levenberg_marquardt(b, problem, Eigen::Vector2d(0.3, -1.0), 1000);
  ASSERT_EQ(a.trace().size(), b.trace().size());
  for (std::size_t i = 0; i < a.trace().size(); ++i) {
    EXPECT_EQ(a.trace()[i].evaluations, b.trace()[i].evaluations);
    EXPECT_EQ(a.trace()[i].best, b.trace()[i].best);
  }
}

TEST(HammersteinResiduals, SumToTheFitnessTheBatchedKernelComputes) {
  const Measurement data =
      read_measurement(std::string(HYSTBENCH_SOURCE_DIR) + "/problems/hammerstein/data/default.csv", {});
  const HammersteinProblem problem(data, BoucWenForm::Increment, HammersteinProblem::default_bounds());
  Eigen::MatrixXd X(13, 2);
  X.col(0) = HammersteinParams{0.4, 0.0015, 0.0005, 0.2, 0.15, 6e-05, 1.583e-05, 0.001194, 1.0, 0.2, 0.09, -1.0, 0.29}
                 .to_vector();
  X.col(1) = X.col(0) * 1.05;
  Eigen::VectorXd f(2), r(problem.residual_count());
  problem.evaluate(X, f);
  ASSERT_EQ(problem.residual_count(), data.y.size());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(std::isfinite(f[i]));
    problem.residuals(X.col(i), r);
    EXPECT_NEAR(r.squaredNorm(), f[i], 1e-12 * f[i]);
  }
}

}  // namespace
}  // namespace hystbench
