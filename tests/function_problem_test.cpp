#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "problems/functions/function_problem.hpp"
#include "problems/functions/test_functions.hpp"

namespace hystbench {
namespace {

using nlohmann::json;

double value(const std::string& function, const Eigen::VectorXd& x) {
  return find_test_function(function)->f(x);
}

std::unique_ptr<Problem> build(const json& spec) {
  return make_problem(spec, ".");
}

std::string error_of(const json& spec) {
  try {
    build(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TestFunctions, ZeroAtKnownOptimum) {
  for (const auto& name : test_function_names()) {
    const TestFunction* f = find_test_function(name);
    for (int d : {2, 5, 10}) {
      const Eigen::VectorXd x = Eigen::VectorXd::Constant(d, f->optimum_coordinate);
      // Schwefel's optimum is only known to the precision of its constants.
      const double tolerance = name == "schwefel" ? 1e-6 * d : 1e-12;
      EXPECT_NEAR(f->f(x), 0.0, tolerance) << name << " in dimension " << d;
    }
  }
}

TEST(TestFunctions, HandComputedValues) {
  // sphere(1, 2) = 1 + 4
  EXPECT_DOUBLE_EQ(value("sphere", Eigen::Vector2d(1, 2)), 5.0);
  // ellipsoid in D = 2 weighs x1 by 1 and x2 by 10^6; in D = 3, x2 by 10^3.
  EXPECT_DOUBLE_EQ(value("ellipsoid", Eigen::Vector2d(1, 1)), 1000001.0);
  EXPECT_DOUBLE_EQ(value("ellipsoid", Eigen::Vector3d(0, 1, 0)), 1000.0);
  EXPECT_DOUBLE_EQ(value("ellipsoid", Eigen::VectorXd::Constant(1, 3.0)), 9.0);
  // rosenbrock(0, 0) = 100 (0 - 0)^2 + (1 - 0)^2; (-1, 1): 0 + 2^2.
  EXPECT_DOUBLE_EQ(value("rosenbrock", Eigen::Vector2d(0, 0)), 1.0);
  EXPECT_DOUBLE_EQ(value("rosenbrock", Eigen::Vector2d(-1, 1)), 4.0);
  // rastrigin(1, 0) = 20 + (1 - 10 cos 2pi) + (0 - 10 cos 0) = 20 - 9 - 10.
  EXPECT_NEAR(value("rastrigin", Eigen::Vector2d(1, 0)), 1.0, 1e-12);
  // rastrigin(0.5) = 10 + 0.25 - 10 cos pi.
  EXPECT_NEAR(value("rastrigin", Eigen::VectorXd::Constant(1, 0.5)), 20.25, 1e-12);
  // ackley(1, 1): sqrt(sum x^2 / D) = 1 and cos 2pi = 1, leaving 20 (1 - e^-0.2).
  EXPECT_NEAR(value("ackley", Eigen::Vector2d(1, 1)), 20.0 * (1.0 - std::exp(-0.2)), 1e-12);
  EXPECT_NEAR(value("ackley", Eigen::Vector2d(0, 0)), 0.0, 1e-12);
  // griewank(pi, 0) = 1 + pi^2 / 4000 - cos(pi) cos(0) = 2 + pi^2 / 4000.
  const double pi = std::numbers::pi;
  EXPECT_NEAR(value("griewank", Eigen::Vector2d(pi, 0)), 2.0 + pi * pi / 4000.0, 1e-12);
  EXPECT_NEAR(value("griewank", Eigen::Vector2d(0, 0)), 0.0, 1e-12);
  // schwefel(0, 0) is just the offset, 418.9828872724338 per coordinate.
  EXPECT_NEAR(value("schwefel", Eigen::Vector2d(0, 0)), 2 * 418.9828872724338, 1e-9);
}

TEST(TestFunctions, PositiveAwayFromOptimum) {
  const Eigen::Vector3d x(0.3, -1.7, 2.2);
  for (const auto& name : test_function_names()) EXPECT_GT(value(name, x), 0.0) << name;
}

TEST(FunctionProblem, BatchEqualsColumnByColumn) {
  std::mt19937_64 rng(42);
  for (const auto& name : test_function_names()) {
    const FunctionProblem problem(name, 5);
    const Bounds& b = problem.bounds();
    std::uniform_real_distribution<double> u(b.lower[0], b.upper[0]);
    Eigen::MatrixXd X(5, 7);
    for (double& v : X.reshaped()) v = u(rng);
    Eigen::VectorXd batch(7);
    problem.evaluate(X, batch);
    for (int j = 0; j < X.cols(); ++j) {
      Eigen::VectorXd one(1);
      problem.evaluate(X.col(j), one);
      EXPECT_EQ(batch[j], one[0]) << name << " column " << j;
    }
  }
}

TEST(FunctionProblem, RegistryBuildsFromJson) {
  const auto problem = build({{"type", "function"}, {"name", "rastrigin"}, {"dimension", 10}});
  EXPECT_EQ(problem->name(), "rastrigin-10");
  ASSERT_EQ(problem->dimension(), 10);
  EXPECT_DOUBLE_EQ(problem->bounds().lower[3], -5.12);
  EXPECT_DOUBLE_EQ(problem->bounds().upper[9], 5.12);
  EXPECT_EQ(problem->bounds().names.front(), "x1");
  EXPECT_EQ(problem->bounds().names.back(), "x10");

  const json d = problem->describe();
  EXPECT_EQ(d["name"], "rastrigin-10");
  EXPECT_EQ(d["function"], "rastrigin");
  EXPECT_EQ(d["dimension"], 10);
  EXPECT_EQ(d["optimum_value"], 0.0);
  EXPECT_EQ(d["optimum_x"], json(std::vector<double>(10, 0.0)));
}

TEST(FunctionProblem, BoundsOverride) {
  const auto problem = build({{"type", "function"}, {"name", "rosenbrock"}, {"dimension", 3},
                              {"lower", -2}, {"upper", 2.5}});
  EXPECT_EQ(problem->bounds().lower, Eigen::VectorXd::Constant(3, -2.0));
  EXPECT_EQ(problem->bounds().upper, Eigen::VectorXd::Constant(3, 2.5));
  EXPECT_EQ(problem->describe()["optimum_x"], json(std::vector<double>(3, 1.0)));
}

TEST(FunctionProblem, OptimumOutsideOverriddenBoundsIsNotClaimed) {
  const auto problem = build({{"type", "function"}, {"name", "sphere"}, {"dimension", 2},
                              {"lower", 1}, {"upper", 3}});
  EXPECT_TRUE(problem->describe()["optimum_value"].is_null());
}

TEST(FunctionProblem, ErrorsNameTheirKey) {
  EXPECT_EQ(error_of({{"type", "function"}, {"name", "sphere"}, {"dimension", 0}}),
            "problem.dimension = 0 is out of range; it must be in [1, 2147483647]");
  EXPECT_EQ(error_of({{"type", "function"}, {"name", "sphere"}, {"dimension", 2},
                      {"lower", 5}, {"upper", 1}}),
            "problem.lower = 5 must be below problem.upper = 1");

  const std::string unknown = error_of({{"type", "function"}, {"name", "nope"}, {"dimension", 2}});
  EXPECT_NE(unknown.find("problem.name"), std::string::npos) << unknown;
  for (const auto& name : test_function_names())
    EXPECT_NE(unknown.find(name), std::string::npos) << unknown;

  const std::vector<json> bad_dimensions = {-3, 2.5, "10", 3000000000LL};
  for (const json& d : bad_dimensions)
    EXPECT_NE(error_of({{"type", "function"}, {"name", "sphere"}, {"dimension", d}})
                  .find("problem.dimension"),
              std::string::npos)
        << d;
  EXPECT_NE(error_of({{"type", "function"}, {"name", "sphere"}}).find("problem.dimension"),
            std::string::npos);
  EXPECT_NE(error_of({{"type", "function"}, {"name", "rosenbrock"}, {"dimension", 1}})
                .find("problem.dimension = 1"),
            std::string::npos);
  EXPECT_NE(error_of({{"type", "function"}, {"name", "sphere"}, {"dimension", 2},
                      {"upper", "high"}})
                .find("problem.upper"),
            std::string::npos);
  EXPECT_NE(error_of({{"type", "function"}, {"dimension", 2}}).find("problem.name"),
            std::string::npos);
  const std::string extra =
      error_of({{"type", "function"}, {"name", "sphere"}, {"dimension", 2}, {"dim", 2}});
  EXPECT_NE(extra.find("problem"), std::string::npos) << extra;
  EXPECT_NE(extra.find("'dim'"), std::string::npos) << extra;
}

}  // namespace
}  // namespace hystbench
