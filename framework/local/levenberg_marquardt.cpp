#include "framework/local/levenberg_marquardt.hpp"

#include <unsupported/Eigen/NonLinearOptimization>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hystbench {
namespace {

// A diverging candidate gets residuals this large: MINPACK then rejects the
// step and shrinks its trust region, as it would for any worse point.
constexpr double kDivergedResidual = 1e100;

// Forward-difference step in normalised coordinates: about the square root
// of the machine epsilon, the classic choice for a function known to full
// precision.
const double kDifferenceStep = std::sqrt(std::numeric_limits<double>::epsilon());

class Residuals {
 public:
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  Residuals(EvaluationContext& ctx, const LeastSquaresProblem& problem, long allowed)
      : ctx_(ctx), problem_(problem), allowed_(allowed),
        lower_(ctx.bounds().lower), range_(ctx.bounds().upper - ctx.bounds().lower) {}

  int inputs() const { return int(lower_.size()); }
  int values() const { return int(problem_.residual_count()); }
  bool out_of_budget() { return used_ >= allowed_ || ctx_.stopped(); }

  Eigen::VectorXd normalise(const Eigen::VectorXd& x) const { return (x - lower_).cwiseQuotient(range_); }
  Eigen::VectorXd physical(const Eigen::VectorXd& z) const {
    return ctx_.bounds().clamp(lower_ + range_.cwiseProduct(z));
  }

  // MINPACK's contract: a negative return stops the minimisation.
  int operator()(const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    if (out_of_budget()) return -1;
    ++used_;
    const Eigen::VectorXd x = physical(z);
    r.resize(values());
    if (std::isfinite(ctx_.evaluate(x)))
      problem_.residuals(x, r);
    else
      r.setConstant(kDivergedResidual);
    last_z_ = z;
    last_r_ = r;
    return 0;
  }

  // MINPACK asks for the Jacobian at the point it has just accepted, which
  // is the last one evaluated: its residuals are reused, not re-evaluated.
  int df(const Eigen::VectorXd& z, Eigen::MatrixXd& jacobian) {
    Eigen::VectorXd r0 = last_r_;
    if (last_z_.size() != z.size() || last_z_ != z) {
      if ((*this)(z, r0) < 0) return -1;
    }
    jacobian.resize(values(), inputs());
    Eigen::VectorXd zj = z, rj;
    for (int j = 0; j < inputs(); ++j) {
      // Step inwards at the upper bound so the column is not flat.
      const double h = z[j] + kDifferenceStep <= 1.0 ? kDifferenceStep : -kDifferenceStep;
      zj[j] = z[j] + h;
      if ((*this)(zj, rj) < 0) return -1;
      jacobian.col(j) = (rj - r0) / h;
      zj[j] = z[j];
    }
    last_z_ = z;
    last_r_ = r0;
    return 0;
  }

 private:
  EvaluationContext& ctx_;
  const LeastSquaresProblem& problem_;
  long allowed_;
  long used_ = 0;
  Eigen::VectorXd lower_, range_;
  Eigen::VectorXd last_z_, last_r_;
};

std::string describe(Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (status) {
    case UserAsked:
      return "budget";
    case RelativeReductionTooSmall:
    case RelativeErrorTooSmall:
    case RelativeErrorAndReductionTooSmall:
    case CosinusTooSmall:
      return "converged";
    default:
      return "no progress";
  }
}

}  // namespace

std::string run_levenberg_marquardt(EvaluationContext& ctx, const LeastSquaresProblem& problem,
                                    const Eigen::VectorXd& x0, long max_evaluations) {
  const long allowed = std::min(max_evaluations, ctx.remaining_evaluations());
  if (allowed <= 0 || ctx.stopped()) return "budget";
  Residuals residuals(ctx, problem, allowed);
  Eigen::VectorXd z = residuals.normalise(ctx.bounds().clamp(x0));
  Eigen::LevenbergMarquardt<Residuals> lm(residuals);
  // The budget is enforced by the functor; MINPACK's own limit must not
  // end the search first.
  lm.parameters.maxfev = std::numeric_limits<int>::max();
  // Tight tolerances: a polish runs until its SSE stops moving, and the
  // target or the budget usually ends it before these do.
  lm.parameters.ftol = 1e-12;
  lm.parameters.xtol = 1e-12;
  return describe(lm.minimize(z));
}

}  // namespace hystbench
