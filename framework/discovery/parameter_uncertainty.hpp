#pragma once
// Standard errors of fitted parameters from the Jacobian at the optimum
// (Gauss–Newton covariance, e.g. Seber & Wild, Nonlinear Regression, 1989,
// §2.1): Cov(x) ≈ s² (JᵀJ)⁻¹ with s² = SSE / (N − k), J the derivative of
// the estimation residuals with respect to the normalised parameters.
//
// They assume white residuals: with a coloured residual they are too small.
// A parameter on a direction that the data do not determine (a near-null
// eigenvector of JᵀJ) gets an infinite standard error, and a pair whose
// correlation is close to ±1 trade against each other (a delay against an
// ARX block's own lag): the fit can drift along that pair.
#include "framework/core/eigen.hpp"
#include <utility>

#include "framework/model/model.hpp"

namespace hystbench {

struct ParameterUncertainty {
  Eigen::VectorXd sd;           // normalised units; +inf where undetermined, NaN when unknown
  Eigen::MatrixXd correlation;  // NaN where a standard error is not finite
  bool available = false;       // false when the model is unstable at x

  // The pair (i < j) with the largest finite |correlation|, and its value;
  // {-1, -1} and 0 when there is none.
  std::pair<std::pair<int, int>, double> most_correlated() const;
};

ParameterUncertainty parameter_uncertainty(const Model& model, const Eigen::VectorXd& x,
                                           const ModelData& data);

}  // namespace hystbench
