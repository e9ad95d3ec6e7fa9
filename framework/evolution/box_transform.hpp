#pragma once
// pycma's default box-constraint handling for CMA-ES, "BoundTransform"
// (the piecewise linear-quadratic transformation,
// docs/algorithms.md#boundtransform).
//
// CMA-ES samples without bounds and evaluates f at the transformed point,
// keeping the untransformed one for its update. The map is the identity on
// most of [l, u], quadratic within a margin of each bound and periodic
// (mirrored) outside, so every real number lands inside the box and the map
// is smooth everywhere.
#include "framework/core/eigen.hpp"

namespace hystbench {

// Image of y in [l, u]. Margins: a = min((u - l)/2, 0.05 max(|bound|, 1)),
// i.e. 0.05 at both ends of [0, 1]. A degenerate interval (u <= l) gives l.
double box_transform(double y, double l, double u);

// Componentwise onto the unit box [0, 1]^n, where the optimizers work.
Eigen::VectorXd unit_box_transform(const Eigen::Ref<const Eigen::VectorXd>& y);

}  // namespace hystbench
