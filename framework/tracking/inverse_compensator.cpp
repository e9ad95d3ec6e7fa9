#include "framework/tracking/inverse_compensator.hpp"

#include <cmath>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

constexpr int kMaxEvaluations = 80;

}  // namespace

double InverseStatistics::rms_residual() const {
  const long solved = samples - saturated;
  return solved > 0 ? std::sqrt(sum_squared_residual / double(solved)) : 0.0;
}

InverseCompensator::InverseCompensator(const IdentifiedModel& model, const std::string& description, double u_min,
                                       double u_max, double tolerance)
    : model_(model.clone()), u_min_(u_min), u_max_(u_max), tolerance_(tolerance) {
  if (!(u_min < u_max)) throw InputError("inverse: the input range needs u_min < u_max");
  if (!(tolerance > 0.0)) throw InputError("inverse: the tolerance must be positive");
  model_->reset();
  // A front whose output does not move with the current input (an input
  // delay of a sample or more) has no inverse at the current sample.
  if (!(std::abs(trial(u_max) - trial(u_min)) > tolerance))
    throw InputError("inverse: the front of " + description +
                     " does not respond to the current input (an input delay?); inverse compensation "
                     "needs a front whose output moves with the input it is given");
}

InverseCompensator::InverseCompensator(const InverseCompensator& o)
    : model_(o.model_->clone()), u_min_(o.u_min_), u_max_(o.u_max_), tolerance_(o.tolerance_), stats_(o.stats_) {}

void InverseCompensator::reset() {
  model_->reset();
  stats_ = {};
}

double InverseCompensator::trial(double u) { return model_->trial_front(u); }

// Regula falsi with the Illinois modification: superlinear on the nearly
// affine fronts of physical models, and never leaves the bracket.
double InverseCompensator::step(double w_desired) {
  double a = u_min_, b = u_max_;
  double fa = trial(a) - w_desired, fb = trial(b) - w_desired;
  int evaluations = 2;
  double u = b, fu = fb;
  const bool bracketed = fa * fb < 0.0;
  if (!bracketed) {
    if (std::abs(fa) <= std::abs(fb)) u = a, fu = fa;
  } else {
    while (evaluations < kMaxEvaluations && std::abs(fu) > tolerance_ &&
           std::abs(b - a) > 1e-13 * (u_max_ - u_min_)) {
      u = (a * fb - b * fa) / (fb - fa);
      fu = trial(u) - w_desired;
      ++evaluations;
      if (fu * fb < 0.0) {
        a = b, fa = fb;
      } else {
        fa /= 2;  // the end kept twice: halve its weight
      }
      b = u, fb = fu;
    }
  }
  ++stats_.samples;
  if (!bracketed && std::abs(fu) > tolerance_) {
    ++stats_.saturated;
  } else {
    stats_.max_residual = std::max(stats_.max_residual, std::abs(fu));
    stats_.sum_squared_residual += fu * fu;
  }
  stats_.max_evaluations = std::max(stats_.max_evaluations, evaluations);
  model_->step_front(u);
  return u;
}

}  // namespace hystbench
