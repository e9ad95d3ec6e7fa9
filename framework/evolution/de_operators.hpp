#pragma once
// Differential-evolution mutation and crossover (algorithms.md §1.2, §1.3),
// shared by every DE-family plugin.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "framework/core/rng.hpp"

namespace hystbench {

enum class DeStrategy { Rand1, Best1, CurrentToBest1, CurrentToPbest1 };

const std::vector<std::string>& de_strategy_names();  // "rand/1", "best/1", ...
DeStrategy de_strategy_from_string(const std::string& name);

// What a mutation may read: the population (one column per member), its
// ranking (best first) and how many top members form the p-best set.
struct DePopulationView {
  const Eigen::MatrixXd& X;
  const std::vector<int>& order;
  int pbest_count;
};

// Mutant vector for target i with scale factor F. Draws its random indices
// from rng; for current-to-pbest/1 there is no archive.
Eigen::VectorXd de_mutant(DeStrategy strategy, const DePopulationView& pop, int i, double F,
                          Rng& rng);

// Binomial crossover with j_rand: each component from the mutant with
// probability CR, and at least component j_rand.
Eigen::VectorXd binomial_crossover(const Eigen::Ref<const Eigen::VectorXd>& target,
                                   const Eigen::Ref<const Eigen::VectorXd>& mutant, double CR,
                                   Rng& rng);

// n_p = max(2, round(p * NP)) (algorithms.md §1.2).
int pbest_count(double p, int np);

}  // namespace hystbench
