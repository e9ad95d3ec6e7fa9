#pragma once
// A classic test function (rastrigin, rosenbrock, ...) as a Problem, for
// checking optimizers where the answer is known. Experiment file:
//   {"type": "function", "name": "rastrigin", "dimension": 10,
//    "lower": -5.12, "upper": 5.12}          // lower/upper optional
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <string>

#include "framework/core/problem.hpp"
#include "framework/core/registry.hpp"
#include "problems/functions/test_functions.hpp"

namespace hystbench {

class FunctionProblem : public Problem {
 public:
  // Bounds default to the function's standard domain. Throws InputError
  // naming the experiment key at fault (problem.name, problem.dimension, ...).
  FunctionProblem(const std::string& function, int dimension,
                  std::optional<double> lower = std::nullopt,
                  std::optional<double> upper = std::nullopt);
  // From the experiment's validated "problem" options. Throws InputError.
  static std::unique_ptr<FunctionProblem> from_options(const Params& options);
  static ProblemInfo info();  // registry entry "function"

  std::string name() const override;
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                Eigen::Ref<Eigen::VectorXd> f) const override;
  // The known optimum is reported only while it lies inside the bounds: a
  // user-narrowed box that excludes it has a different, unknown minimum.
  nlohmann::json describe() const override;

 private:
  const TestFunction* function_;
  Bounds bounds_;
};

}  // namespace hystbench
