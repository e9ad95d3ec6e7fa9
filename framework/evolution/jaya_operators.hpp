#pragma once
// The Jaya move (docs/algorithms.md#jaya, Rao 2016), shared by Jaya and the
// Jaya+DE hybrid.
#include "framework/core/eigen.hpp"

#include "framework/core/problem.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {

// One candidate per column of X:
//   x'_j = x_j + r1 (best_j - |x_j|) - r2 (worst_j - |x_j|),
// r1, r2 ~ U(0,1) fresh per (candidate, variable), best and worst taken once
// from the current population (ties: lowest index best, highest index
// worst), repaired by CLIP. Meant for normalised coordinates, where |x| = x.
Eigen::MatrixXd jaya_candidates(const Eigen::MatrixXd& X, const Eigen::VectorXd& fx,
                                const Bounds& bounds, Rng& rng);

}  // namespace hystbench
