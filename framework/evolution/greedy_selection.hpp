#pragma once
// One-to-one greedy replacement with the "<=" tie rule (docs/algorithms.md#selection):
// candidate i replaces member i when it is not worse.
#include "framework/core/eigen.hpp"

namespace hystbench {

// Considers only the first `evaluated` candidates (the rest were not
// evaluated because the budget ran out).
void replace_if_not_worse(Eigen::MatrixXd& X, Eigen::VectorXd& fx, const Eigen::MatrixXd& U,
                          const Eigen::VectorXd& fu, Eigen::Index evaluated);

}  // namespace hystbench
