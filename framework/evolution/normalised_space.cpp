#include "framework/evolution/normalised_space.hpp"

#include <algorithm>

namespace hystbench {

NormalisedSpace::NormalisedSpace(const Bounds& box) : box_(box) {
  unit_.lower = Eigen::VectorXd::Zero(box.dimension());
  unit_.upper = Eigen::VectorXd::Ones(box.dimension());
  unit_.names = box.names;
}

Eigen::MatrixXd NormalisedSpace::to_box(const Eigen::MatrixXd& Z) const {
  Eigen::MatrixXd X(Z.rows(), Z.cols());
  for (Eigen::Index i = 0; i < Z.cols(); ++i) {
    for (Eigen::Index j = 0; j < Z.rows(); ++j) {
      const double lo = box_.lower[j], hi = box_.upper[j];
      X(j, i) = std::clamp(lo + Z(j, i) * (hi - lo), lo, hi);
    }
  }
  return X;
}

Eigen::MatrixXd NormalisedSpace::to_unit(const Eigen::MatrixXd& X) const {
  const Eigen::VectorXd width = box_.upper - box_.lower;
  Eigen::MatrixXd Z(X.rows(), X.cols());
  for (Eigen::Index i = 0; i < X.cols(); ++i)
    for (Eigen::Index j = 0; j < X.rows(); ++j)
      Z(j, i) = width[j] > 0 ? (X(j, i) - box_.lower[j]) / width[j] : 0.0;
  return Z;
}

Eigen::Index NormalisedSpace::evaluate(EvaluationContext& ctx, const Eigen::MatrixXd& Z,
                                       Eigen::VectorXd& f) const {
  return ctx.evaluate(to_box(Z), f);
}

}  // namespace hystbench
