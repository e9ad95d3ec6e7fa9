#include "problems/functions/function_problem.hpp"

#include <climits>
#include <cmath>
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

std::string read_name(const nlohmann::json& spec) {
  auto it = spec.find("name");
  if (it == spec.end() || !it->is_string())
    throw InputError("problem.name: expected the function's name, one of: " +
                     join(test_function_names()));
  return it->get<std::string>();
}

int read_dimension(const nlohmann::json& spec) {
  auto it = spec.find("dimension");
  if (it == spec.end()) throw InputError("problem.dimension: missing; must be a positive integer");
  // Compared as double so that huge signed or unsigned values cannot wrap; every
  // integer near the int range is exact in a double.
  const bool ok = it->is_number_integer() && it->get<double>() >= 1 && it->get<double>() <= INT_MAX;
  if (!ok) throw InputError("problem.dimension = " + it->dump() + ": must be a positive integer");
  return it->get<int>();
}

std::optional<double> read_bound(const nlohmann::json& spec, const std::string& key) {
  auto it = spec.find(key);
  if (it == spec.end()) return std::nullopt;
  if (!it->is_number() || !std::isfinite(it->get<double>()))
    throw InputError("problem." + key + ": expected a finite number, got " + it->dump());
  return it->get<double>();
}

}  // namespace

ProblemInfo FunctionProblem::info() {
  return {"function",
          "analytic test function with minimum 0 (" + join(test_function_names()) + ")",
          {"type", "name", "dimension", "lower", "upper"},
          [](const nlohmann::json& spec, const std::filesystem::path&) {
            return std::unique_ptr<Problem>(FunctionProblem::from_json(spec));
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

std::unique_ptr<FunctionProblem> FunctionProblem::from_json(const nlohmann::json& spec) {
  require_known_keys(spec, {"type", "name", "dimension", "lower", "upper"}, "problem");
  return std::make_unique<FunctionProblem>(read_name(spec), read_dimension(spec),
                                           read_bound(spec, "lower"), read_bound(spec, "upper"));
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
