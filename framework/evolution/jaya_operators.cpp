#include "framework/evolution/jaya_operators.hpp"

#include <cmath>

#include "framework/evolution/bound_handling.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {

Eigen::MatrixXd jaya_candidates(const Eigen::MatrixXd& X, const Eigen::VectorXd& fx,
                                const Bounds& bounds, Rng& rng) {
  const auto order = rank_order(fx);
  const Eigen::VectorXd best = X.col(order.front());
  const Eigen::VectorXd worst = X.col(order.back());
  Eigen::MatrixXd U(X.rows(), X.cols());
  for (Eigen::Index k = 0; k < X.cols(); ++k) {
    for (Eigen::Index j = 0; j < X.rows(); ++j) {
      const double r1 = rng.uniform(), r2 = rng.uniform();
      const double size = std::abs(X(j, k));
      U(j, k) = X(j, k) + r1 * (best[j] - size) - r2 * (worst[j] - size);
    }
    repair(U.col(k), X.col(k), bounds, BoundHandling::Clip, rng);
  }
  return U;
}

}  // namespace hystbench
