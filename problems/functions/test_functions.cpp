#include "problems/functions/test_functions.hpp"

#include <cmath>
#include <numbers>

namespace hystbench {
namespace {

using Vec = Eigen::Ref<const Eigen::VectorXd>;
constexpr double two_pi = 2.0 * std::numbers::pi;

// Schwefel 2.26. The per-coordinate minimiser solves
// sin(sqrt(x)) + sqrt(x) cos(sqrt(x)) / 2 = 0 inside [-500, 500]; the offset
// is -x* sin(sqrt(x*)) there, which makes the minimum 0 up to the rounding of
// these two constants (well below 1e-6 per coordinate).
constexpr double schwefel_x = 420.9687462275036;
constexpr double schwefel_offset = 418.9828872724338;

double sphere(const Vec& x) { return x.squaredNorm(); }

// Condition number 1e6: weights rise geometrically from 1 to 1e6.
double ellipsoid(const Vec& x) {
  const auto d = x.size();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < d; ++i) {
    const double w = d == 1 ? 1.0 : std::pow(10.0, 6.0 * double(i) / double(d - 1));
    sum += w * x[i] * x[i];
  }
  return sum;
}

double rosenbrock(const Vec& x) {
  const auto n = x.size() - 1;
  const auto head = x.head(n).array();
  return (100.0 * (x.tail(n).array() - head.square()).square() + (1.0 - head).square()).sum();
}

double rastrigin(const Vec& x) {
  const auto a = x.array();
  return 10.0 * double(x.size()) + (a.square() - 10.0 * (two_pi * a).cos()).sum();
}

// Grouped as 20(1 - e^a) + (e - e^b) so that the optimum evaluates to exactly 0.
double ackley(const Vec& x) {
  const double d = double(x.size());
  const auto a = x.array();
  const double spread = std::exp(-0.2 * std::sqrt(a.square().sum() / d));
  const double waves = std::exp((two_pi * a).cos().sum() / d);
  return 20.0 * (1.0 - spread) + (std::numbers::e - waves);
}

double griewank(const Vec& x) {
  double product = 1.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) product *= std::cos(x[i] / std::sqrt(double(i + 1)));
  return 1.0 + x.squaredNorm() / 4000.0 - product;
}

double schwefel(const Vec& x) {
  const auto a = x.array();
  return schwefel_offset * double(x.size()) - (a * a.abs().sqrt().sin()).sum();
}

const std::vector<TestFunction>& table() {
  static const std::vector<TestFunction> functions = {
      {"sphere", sphere, -100.0, 100.0, 0.0, 0.0, 1},
      {"ellipsoid", ellipsoid, -100.0, 100.0, 0.0, 0.0, 1},
      {"rosenbrock", rosenbrock, -30.0, 30.0, 1.0, 0.0, 2},
      {"rastrigin", rastrigin, -5.12, 5.12, 0.0, 0.0, 1},
      {"ackley", ackley, -32.768, 32.768, 0.0, 0.0, 1},
      {"griewank", griewank, -600.0, 600.0, 0.0, 0.0, 1},
      {"schwefel", schwefel, -500.0, 500.0, schwefel_x, 0.0, 1},
  };
  return functions;
}

}  // namespace

const TestFunction* find_test_function(const std::string& name) {
  for (const auto& f : table())
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<std::string> test_function_names() {
  std::vector<std::string> names;
  for (const auto& f : table()) names.push_back(f.name);
  return names;
}

}  // namespace hystbench
