#pragma once
// Differential-evolution mutation and crossover, shared by every DE-family
// plugin (docs/algorithms.md#mutation-strategies,
// docs/algorithms.md#binomial-crossover).
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/core/rng.hpp"

namespace hystbench {

// Pbest1 ("pbest/1") is x_pbest + F (x_r1 - x_r2): the base-vector reading of
// AmFMMDE's DE/pbest/1 (docs/algorithms.md#amfmmde).
enum class DeStrategy { Rand1, Best1, CurrentToBest1, CurrentToPbest1, Pbest1 };

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

// DE/neighbor/1 of RNDE (docs/algorithms.md#neighbour-mutation) for target i
// of population X (fitness f): the base vector is the best (first drawn on ties) of
// `neighbors` members drawn from the population without i; r1, r2 exclude i
// and that base. Requires neighbors <= NP - 1 and NP >= 4.
Eigen::VectorXd de_neighbor_mutant(const Eigen::MatrixXd& X, const Eigen::VectorXd& f, int i,
                                   double F, int neighbors, Rng& rng);

// Default neighbour count of DE/neighbor/1: max(3, round(0.1 NP)), at most
// NP - 1 (docs/algorithms.md#neighbour-mutation, RECONSTRUCTION).
int default_neighbor_count(int np);

// Binomial crossover with j_rand: each component from the mutant with
// probability CR, and at least component j_rand.
Eigen::VectorXd binomial_crossover(const Eigen::Ref<const Eigen::VectorXd>& target,
                                   const Eigen::Ref<const Eigen::VectorXd>& mutant, double CR,
                                   Rng& rng);

// n_p = max(2, round(p * NP)) (docs/algorithms.md#mutation-strategies).
int pbest_count(double p, int np);

}  // namespace hystbench
