#pragma once
// Building blocks of population methods: initial sampling, index draws,
// ranking.
#include "framework/core/eigen.hpp"
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {

// NP points drawn uniformly in the box, one per column (docs/algorithms.md#initial-population).
Eigen::MatrixXd uniform_population(const Bounds& bounds, int np, Rng& rng);

// `count` distinct indices from {0..n-1}, all different from the ones in
// `exclude`. Requires n - |exclude| >= count.
std::vector<int> distinct_indices(Rng& rng, int n, int count, std::vector<int> exclude);

// Indices of f sorted by increasing fitness; ties keep index order.
std::vector<int> rank_order(const Eigen::VectorXd& f);

}  // namespace hystbench
