#include "framework/evolution/pso_coefficients.hpp"

#include <cmath>
#include <stdexcept>

#include "framework/core/text.hpp"

namespace hystbench {

double inertia_weight(double w_max, double w_min, double tau) {
  return w_max - (w_max - w_min) * tau;
}

double constriction_factor(double phi, double kappa) {
  if (!(phi > 4.0))
    throw std::invalid_argument("constriction needs c1 + c2 > 4; got " + number_text(phi));
  return 2.0 * kappa / std::abs(2.0 - phi - std::sqrt(phi * phi - 4.0 * phi));
}

}  // namespace hystbench
