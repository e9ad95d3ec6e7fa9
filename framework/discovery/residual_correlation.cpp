#include "framework/discovery/residual_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// 99 % two-sided quantile of the standard normal distribution.
constexpr double kBand99 = 2.58;

Eigen::VectorXd centred(const Eigen::VectorXd& v) { return (v.array() - v.mean()).matrix(); }

double band(Eigen::Index n) { return n > 0 ? kBand99 / std::sqrt(double(n)) : kNaN; }

// Σ_k a_{k−τ} b_k over the k where both exist (τ may be negative).
double lagged_sum(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int tau) {
  const Eigen::Index n = a.size(), shift = std::abs(tau);
  if (shift >= n) return 0.0;
  const Eigen::Index len = n - shift;
  return tau >= 0 ? a.head(len).dot(b.tail(len)) : a.tail(len).dot(b.head(len));
}

void count_outside(Correlation& c) {
  c.outside = int(std::count_if(c.values.begin(), c.values.end(),
                                [&](double v) { return std::abs(v) > c.bound; }));
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

Correlation autocorrelation(const Eigen::VectorXd& e, int max_lag) {
  Correlation c;
  c.bound = band(e.size());
  const Eigen::VectorXd ec = centred(e);
  const double energy = ec.squaredNorm();
  for (int tau = 1; tau <= max_lag; ++tau) {
    c.lags.push_back(tau);
    c.values.push_back(energy > 0 ? lagged_sum(ec, ec, tau) / energy : kNaN);
  }
  count_outside(c);
  return c;
}

Correlation cross_correlation(const Eigen::VectorXd& u, const Eigen::VectorXd& e, int max_lag) {
  Correlation c;
  c.bound = band(e.size());
  const Eigen::VectorXd uc = centred(u), ec = centred(e);
  const double scale = std::sqrt(uc.squaredNorm() * ec.squaredNorm());
  for (int tau = -max_lag; tau <= max_lag; ++tau) {
    c.lags.push_back(tau);
    c.values.push_back(scale > 0 ? lagged_sum(uc, ec, tau) / scale : kNaN);
  }
  count_outside(c);
  return c;
}

int peak_lag(const Correlation& c) {
  int best = 0;
  double best_value = -1;
  for (std::size_t i = 0; i < c.values.size(); ++i)
    if (std::abs(c.values[i]) > best_value) best_value = std::abs(c.values[i]), best = c.lags[i];
  return best;
}

LjungBox ljung_box(const Eigen::VectorXd& e, int max_lags) {
  LjungBox lb;
  const Eigen::Index n = e.size();
  lb.lags = std::max(1, int(std::min<Eigen::Index>(max_lags, n / 5)));
  if (!e.allFinite()) {  // a diverged model: nothing can be said, least of all "white"
    lb.q = lb.p_value = std::numeric_limits<double>::quiet_NaN();
    return lb;
  }
  if (n < 2) return lb;
  const Correlation r = autocorrelation(e, lb.lags);
  double sum = 0;
  for (int tau = 1; tau <= lb.lags && tau < n; ++tau) {
    const double v = r.values[std::size_t(tau - 1)];
    if (std::isnan(v)) return lb;  // constant residual: nothing to test
    sum += v * v / double(n - tau);
  }
  lb.q = double(n) * double(n + 2) * sum;
  lb.p_value = chi_squared_survival(lb.q, lb.lags);
  return lb;
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

}  // namespace hystbench
