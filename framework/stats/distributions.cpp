#include "framework/stats/distributions.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hystbench::stats {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kTiny = 1e-300;  // Lentz: stands in for a zero denominator
constexpr double kEps = 1e-16;
constexpr int kMaxTerms = 10000;  // terms grow like sqrt(max(a, b))

double not_tiny(double v) { return std::abs(v) < kTiny ? kTiny : v; }

// Continued fraction for I_x(a, b) (Numerical Recipes betacf), converging
// for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 / not_tiny(1.0 - qab * x / qap), h = d;
  for (int m = 1; m <= kMaxTerms; ++m) {
    const double m2 = 2.0 * m;
    const double even = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 / not_tiny(1.0 + even * d);
    c = not_tiny(1.0 + even / c);
    h *= d * c;
    const double odd = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 / not_tiny(1.0 + odd * d);
    c = not_tiny(1.0 + odd / c);
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return h;
}

// x^a y^b / B(a, b) with y = 1 - x passed separately: for f_survival, y
// computed as 1 - x would lose the digits of a small y.
double beta_prefactor(double a, double b, double x, double y) {
  return std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                  b * std::log(y));
}

double regularized_beta(double a, double b, double x, double y) {
  if (x <= 0.0) return 0.0;
  if (y <= 0.0) return 1.0;
  const double front = beta_prefactor(a, b, x, y);
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, y) / b;
}

// Series of P(a, x), for x < a + 1.
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 1000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-16) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction of Q(a, x), for x >= a + 1 (modified Lentz).
double gamma_q_fraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

void check_gamma_arguments(double a, double x) {
  if (!(a > 0) || !(x >= 0))
    throw std::invalid_argument("incomplete gamma: needs a > 0 and x >= 0");
}

}  // namespace

double normal_cdf(double z) { return 0.5 * std::erfc(-z / kSqrt2); }

double normal_two_sided_p(double z) { return std::erfc(std::abs(z) / kSqrt2); }

double incomplete_beta(double a, double b, double x) {
  if (!(a > 0) || !(b > 0) || !(x >= 0 && x <= 1))
    throw std::invalid_argument("incomplete beta: needs a > 0, b > 0 and 0 <= x <= 1");
  return regularized_beta(a, b, x, 1.0 - x);
}

double f_survival(double f, double d1, double d2) {
  if (!(d1 > 0) || !(d2 > 0) || std::isnan(f))
    throw std::invalid_argument("F distribution: needs d1 > 0, d2 > 0 and a number f");
  if (f <= 0) return 1.0;
  if (std::isinf(f)) return 0.0;
  const double denominator = d2 + d1 * f;
  return regularized_beta(d2 / 2.0, d1 / 2.0, d2 / denominator, d1 * f / denominator);
}

double gamma_p(double a, double x) {
  check_gamma_arguments(a, x);
  if (x == 0) return 0.0;
  return x < a + 1 ? gamma_p_series(a, x) : 1.0 - gamma_q_fraction(a, x);
}

double gamma_q(double a, double x) {
  check_gamma_arguments(a, x);
  if (x == 0) return 1.0;
  return x < a + 1 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

double chi_squared_survival(double x, double k) {
  if (x <= 0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return gamma_q(k / 2.0, x / 2.0);
}

}  // namespace hystbench::stats
