#pragma once
// The unit cube z in [0,1]^D and its affine map to the box,
// x_j = l_j + z_j (u_j - l_j) (docs/algorithms.md#normalised-coordinates).
// Methods whose steps
// depend on the scale of the coordinates (Jaya's |x| term, PSO velocity
// limits) search in z so that every parameter counts alike whatever its
// physical range.
#include "framework/core/eigen.hpp"

#include "framework/core/evaluation_context.hpp"
#include "framework/core/problem.hpp"

namespace hystbench {

class NormalisedSpace {
 public:
  explicit NormalisedSpace(const Bounds& box);

  int dimension() const { return unit_.dimension(); }
  // [0,1]^D, for repair() and uniform_population() in z.
  const Bounds& unit() const { return unit_; }

  // Box points of the columns of Z (each in [0,1]^D); clamped so that
  // rounding of l + z (u - l) never steps outside the box.
  Eigen::MatrixXd to_box(const Eigen::MatrixXd& Z) const;
  // z of the columns of X; a component whose bounds coincide maps to 0.
  Eigen::MatrixXd to_unit(const Eigen::MatrixXd& X) const;

  // Evaluates the columns of Z through ctx (see EvaluationContext::evaluate).
  Eigen::Index evaluate(EvaluationContext& ctx, const Eigen::MatrixXd& Z,
                        Eigen::VectorXd& f) const;

 private:
  Bounds box_;
  Bounds unit_;
};

}  // namespace hystbench
