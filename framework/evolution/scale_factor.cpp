#include "framework/evolution/scale_factor.hpp"

#include <cmath>

namespace hystbench {

double time_varying_scale_factor(double f_min, double f_max, double tau) {
  return f_max - (f_max - f_min) * tau;
}

double random_scale_factor(double u) { return 0.5 * (1.0 + u); }

double uniform_scale_factor(double f_min, double f_max, double u) {
  return f_min + u * (f_max - f_min);
}

double amf1_scale_factor(double f_min, double f_max, double u, double tau) {
  return f_min + (f_max - f_min) * u * (1.0 - tau);
}

double amf3_scale_factor(double f0, double tau, double inverse_gmax) {
  // At tau = 1 with inverse_gmax = 0 the inner ratio is +inf and lambda
  // becomes exp(-inf) = 0, the intended end point.
  const double lambda = std::exp(1.0 - 1.0 / (1.0 + inverse_gmax - tau));
  return f0 * std::exp2(lambda);
}

}  // namespace hystbench
