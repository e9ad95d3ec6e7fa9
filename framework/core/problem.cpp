#include "framework/core/problem.hpp"

namespace hystbench {

bool Bounds::contains(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return x.size() == lower.size() && (x.array() >= lower.array()).all() &&
         (x.array() <= upper.array()).all();
}

Eigen::VectorXd Bounds::clamp(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return x.cwiseMax(lower).cwiseMin(upper);
}

}  // namespace hystbench
