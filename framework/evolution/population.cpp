#include "framework/evolution/population.hpp"

#include <algorithm>
#include <numeric>

namespace hystbench {

Eigen::MatrixXd uniform_population(const Bounds& bounds, int np, Rng& rng) {
  Eigen::MatrixXd X(bounds.dimension(), np);
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < bounds.dimension(); ++j)
      X(j, i) = rng.uniform(bounds.lower[j], bounds.upper[j]);
  return X;
}

std::vector<int> distinct_indices(Rng& rng, int n, int count, std::vector<int> exclude) {
  std::vector<int> picked;
  while (static_cast<int>(picked.size()) < count) {
    const int r = static_cast<int>(rng.integer(0, n - 1));
    if (std::find(exclude.begin(), exclude.end(), r) != exclude.end()) continue;
    picked.push_back(r);
    exclude.push_back(r);
  }
  return picked;
}

std::vector<int> rank_order(const Eigen::VectorXd& f) {
  std::vector<int> order(f.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return f[a] < f[b]; });
  return order;
}

}  // namespace hystbench
