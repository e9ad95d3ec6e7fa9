#pragma once
// A parameter point at which every effect of a model acts: gain 1.3 and
// every other parameter a fraction `step` of the way from its neutral value
// to a bound (the upper one when there is room).
#include "framework/core/eigen.hpp"

#include "framework/model/model.hpp"

namespace hystbench::test_support {

inline Eigen::VectorXd active_point(const Model& model, double step) {
  Eigen::VectorXd x = model.neutral();
  x[0] = 1.3;
  for (int i = 1; i < model.dimension(); ++i) {
    const auto& p = model.parameter(i);
    const double room = p.upper > p.neutral ? p.upper - p.neutral : p.lower - p.neutral;
    x[i] = p.neutral + step * room;
  }
  return x;
}

}  // namespace hystbench::test_support
