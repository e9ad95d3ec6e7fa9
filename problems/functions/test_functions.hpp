#pragma once
// Classic analytic benchmark functions. Their minima are known exactly, so an
// optimizer can be checked against the truth before it is trusted on
// measured data, where the best attainable fitness is unknown.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

struct TestFunction {
  using Objective = double (*)(const Eigen::Ref<const Eigen::VectorXd>& x);

  std::string name;
  Objective f = nullptr;
  // Standard search domain, the same on every coordinate.
  double lower = 0.0;
  double upper = 0.0;
  // Every function here is minimised at a point whose coordinates are all
  // equal, so one number describes the minimiser in any dimension.
  double optimum_coordinate = 0.0;
  double optimum_value = 0.0;
  int min_dimension = 1;
};

// nullptr if `name` is not a known function.
const TestFunction* find_test_function(const std::string& name);
// In table order, for messages and listings.
std::vector<std::string> test_function_names();

}  // namespace hystbench
