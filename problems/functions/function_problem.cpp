#include "problems/functions/function_problem.hpp"

#include <climits>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

const TestFunction& lookup(const std::string& name) {
  const TestFunction* f = find_test_function(name);
  if (!f)
    throw InputError("problem.name = \"" + name + "\": unknown function; valid: " +
                     join(test_function_names()));
  return *f;
}

std::optional<double> optional_real(const Params& p, const std::string& key) {
  return p.is_auto(key) ? std::nullopt : std::optional<double>(p.real(key));
}

}  // namespace

ProblemInfo FunctionProblem::info() {
  constexpr double kHuge = std::numeric_limits<double>::max();
  return {"function",
          "analytic test function with minimum 0 (" + join(test_function_names()) + ")",
          {ParamSpec::choice("name", "", test_function_names(), "the test function").require(),
           ParamSpec::integer("dimension", nullptr, 1, INT_MAX, "number of variables").require(),
           ParamSpec::real("lower", nullptr, -kHuge, kHuge,
                           "lower bound of every variable; auto = the function's own box"),
           ParamSpec::real("upper", nullptr, -kHuge, kHuge,
                           "upper bound of every variable; auto = the function's own box")},
          [](const Params& p, const std::filesystem::path&) {
            return std::unique_ptr<Problem>(FunctionProblem::from_options(p));
          }};
}

FunctionProblem::FunctionProblem(const std::string& function, int dimension,
                                 std::optional<double> lower, std::optional<double> upper)
    : function_(&lookup(function)) {
  if (dimension < 1)
    throw InputError("problem.dimension = " + std::to_string(dimension) +
                     ": must be a positive integer");
  if (dimension < function_->min_dimension)
    throw InputError("problem.dimension = " + std::to_string(dimension) + ": " + function +
                     " needs at least " + std::to_string(function_->min_dimension));
  const double lo = lower.value_or(function_->lower);
  const double hi = upper.value_or(function_->upper);
  if (!(lo < hi))
    throw InputError("problem.lower = " + number_text(lo) + " must be below problem.upper = " +
                     number_text(hi));
  bounds_.lower = Eigen::VectorXd::Constant(dimension, lo);
  bounds_.upper = Eigen::VectorXd::Constant(dimension, hi);
  for (int i = 1; i <= dimension; ++i) bounds_.names.push_back(std::string("x").append(std::to_string(i)));
}

std::unique_ptr<FunctionProblem> FunctionProblem::from_options(const Params& p) {
  return std::make_unique<FunctionProblem>(p.text("name"), p.integer("dimension"),
                                           optional_real(p, "lower"), optional_real(p, "upper"));
}

std::string FunctionProblem::name() const {
  return function_->name + "-" + std::to_string(dimension());
}

void FunctionProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                               Eigen::Ref<Eigen::VectorXd> f) const {
  if (X.rows() != dimension() || f.size() != X.cols())
    throw std::invalid_argument(name() + ": evaluate() got a matrix of the wrong shape");
  for (Eigen::Index j = 0; j < X.cols(); ++j) f[j] = function_->f(X.col(j));
}

nlohmann::json FunctionProblem::describe() const {
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(dimension(), function_->optimum_coordinate);
  const bool inside = bounds_.contains(x);
  const nlohmann::json optimum_x = std::vector<double>(x.begin(), x.end());
  return {{"name", name()},
          {"function", function_->name},
          {"dimension", dimension()},
          {"optimum_value", inside ? nlohmann::json(function_->optimum_value) : nullptr},
          {"optimum_x", inside ? optimum_x : nullptr}};
}

}  // namespace hystbench

HYSTBENCH_PROBLEM(hystbench::FunctionProblem)
