#pragma once
// Linear population size reduction (LPSR, L-SHADE;
// docs/algorithms.md#population-size-reduction):
// the population shrinks from N_init to N_min as the budget is used, by
// dropping its worst members.
#include "framework/core/eigen.hpp"

namespace hystbench {

// N(tau) = round((N_min - N_init) tau + N_init), tau in [0, 1].
int linear_population_size(int n_init, int n_min, double tau);

// Keeps the n best columns of X (and entries of f), in their original order;
// among equal fitness the lower index survives.
void keep_best(Eigen::MatrixXd& X, Eigen::VectorXd& f, int n);

}  // namespace hystbench
