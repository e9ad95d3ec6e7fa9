#include "framework/io/synthetic_data.hpp"

#include <cmath>

#include "framework/core/rng.hpp"

namespace hystbench {

double add_relative_noise(Eigen::VectorXd& y, double relative, std::uint64_t seed) {
  const double sd = relative * std::sqrt(y.squaredNorm() / double(y.size()));
  Rng rng(seed);
  for (Eigen::Index k = 0; k < y.size(); ++k) y[k] += sd * rng.normal();
  return sd;
}

}  // namespace hystbench
