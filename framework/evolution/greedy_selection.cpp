#include "framework/evolution/greedy_selection.hpp"

namespace hystbench {

void replace_if_not_worse(Eigen::MatrixXd& X, Eigen::VectorXd& fx, const Eigen::MatrixXd& U,
                          const Eigen::VectorXd& fu, Eigen::Index evaluated) {
  for (Eigen::Index i = 0; i < evaluated; ++i) {
    if (fu[i] <= fx[i]) {
      X.col(i) = U.col(i);
      fx[i] = fu[i];
    }
  }
}

}  // namespace hystbench
