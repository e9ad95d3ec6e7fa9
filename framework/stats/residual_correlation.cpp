#include "framework/stats/residual_correlation.hpp"

#include "framework/stats/distributions.hpp"

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
  lb.p_value = stats::chi_squared_survival(lb.q, lb.lags);
  return lb;
}

}  // namespace hystbench
