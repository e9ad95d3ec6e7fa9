#include "framework/core/problem.hpp"

namespace hystbench {

bool Bounds::contains(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return x.size() == lower.size() && (x.array() >= lower.array()).all() &&
         (x.array() <= upper.array()).all();
}

}  // namespace hystbench
