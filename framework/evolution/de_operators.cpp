#include "framework/evolution/de_operators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "framework/core/text.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {

const std::vector<std::string>& de_strategy_names() {
  static const std::vector<std::string> names{"rand/1", "best/1", "current-to-best/1",
                                               "current-to-pbest/1", "pbest/1"};
  return names;
}

DeStrategy de_strategy_from_string(const std::string& name) {
  return static_cast<DeStrategy>(index_of_name(de_strategy_names(), name, "DE strategy"));
}

int pbest_count(double p, int np) {
  return std::clamp(static_cast<int>(std::lround(p * np)), 2, np);
}

Eigen::VectorXd de_mutant(DeStrategy strategy, const DePopulationView& pop, int i, double F,
                          Rng& rng) {
  const auto& X = pop.X;
  const int np = static_cast<int>(X.cols());
  const int best = pop.order.front();
  switch (strategy) {
    case DeStrategy::Rand1: {
      const auto r = distinct_indices(rng, np, 3, {i});
      return X.col(r[0]) + F * (X.col(r[1]) - X.col(r[2]));
    }
    case DeStrategy::Best1: {
      const auto r = distinct_indices(rng, np, 2, {i});
      return X.col(best) + F * (X.col(r[0]) - X.col(r[1]));
    }
    case DeStrategy::CurrentToBest1: {
      const auto r = distinct_indices(rng, np, 2, {i});
      return X.col(i) + F * (X.col(best) - X.col(i)) + F * (X.col(r[0]) - X.col(r[1]));
    }
    case DeStrategy::CurrentToPbest1: {
      const int pbest = pop.order[rng.integer(0, pop.pbest_count - 1)];
      const auto r = distinct_indices(rng, np, 2, {i});
      return X.col(i) + F * (X.col(pbest) - X.col(i)) + F * (X.col(r[0]) - X.col(r[1]));
    }
    case DeStrategy::Pbest1: {
      const int pbest = pop.order[rng.integer(0, pop.pbest_count - 1)];
      const auto r = distinct_indices(rng, np, 2, {i});
      return X.col(pbest) + F * (X.col(r[0]) - X.col(r[1]));
    }
  }
  throw std::logic_error("unhandled DE strategy");
}

Eigen::VectorXd de_neighbor_mutant(const Eigen::MatrixXd& X, const Eigen::VectorXd& f, int i,
                                   double F, int neighbors, Rng& rng) {
  const int np = static_cast<int>(X.cols());
  const auto candidates = distinct_indices(rng, np, neighbors, {i});
  int base = candidates.front();
  for (int m : candidates)
    if (f[m] < f[base]) base = m;
  const auto r = distinct_indices(rng, np, 2, {i, base});
  return X.col(base) + F * (X.col(r[0]) - X.col(r[1]));
}

int default_neighbor_count(int np) {
  return std::min(np - 1, std::max(3, static_cast<int>(std::lround(0.1 * np))));
}

Eigen::VectorXd binomial_crossover(const Eigen::Ref<const Eigen::VectorXd>& target,
                                   const Eigen::Ref<const Eigen::VectorXd>& mutant, double CR,
                                   Rng& rng) {
  const Eigen::Index d = target.size();
  const Eigen::Index j_rand = rng.integer(0, d - 1);
  Eigen::VectorXd trial = target;
  for (Eigen::Index j = 0; j < d; ++j) {
    // Draw for every component, j_rand included, so the stream of random
    // numbers does not depend on where j_rand fell.
    const bool from_mutant = rng.uniform() <= CR;
    if (from_mutant || j == j_rand) trial[j] = mutant[j];
  }
  return trial;
}

}  // namespace hystbench
