#pragma once
// Validation errors of stage 1 (docs/svr.md#hyperparameters), on scaled
// regression rows and targets.
#include "framework/core/eigen.hpp"

#include "framework/svr/svr_regressor.hpp"

namespace hystbench {

// Mean squared one-step error over `folds` contiguous folds, each predicted
// by an SVR trained on the others. Deterministic.
double blocked_cv_error(const Eigen::MatrixXd& rows, const Eigen::VectorXd& targets,
                        const SvrHyperparameters& h, int folds);

}  // namespace hystbench
