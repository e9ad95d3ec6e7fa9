#include "framework/evolution/population_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/evolution/population.hpp"

namespace hystbench {

int linear_population_size(int n_init, int n_min, double tau) {
  return static_cast<int>(std::lround((n_min - n_init) * tau + n_init));
}

void keep_best(Eigen::MatrixXd& X, Eigen::VectorXd& f, int n) {
  std::vector<int> kept = rank_order(f);
  kept.resize(n);
  std::sort(kept.begin(), kept.end());
  Eigen::MatrixXd X_kept(X.rows(), n);
  Eigen::VectorXd f_kept(n);
  for (int k = 0; k < n; ++k) {
    X_kept.col(k) = X.col(kept[k]);
    f_kept[k] = f[kept[k]];
  }
  X = std::move(X_kept);
  f = std::move(f_kept);
}

}  // namespace hystbench
