#include "framework/model/regressors.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Stop-operator widths tried, as shares of the driving signal's half range.
constexpr double kLoopWidths[] = {1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2};

}  // namespace

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() < 2 || a.size() != b.size()) return kNaN;
  const Eigen::ArrayXd ac = a.array() - a.mean(), bc = b.array() - b.mean();
  const double scale = std::sqrt(ac.square().sum() * bc.square().sum());
  return scale > 0 ? (ac * bc).sum() / scale : kNaN;
}

double standard_deviation(const Eigen::VectorXd& v) {
  if (v.size() < 2) return kNaN;
  return std::sqrt((v.array() - v.mean()).square().sum() / double(v.size() - 1));
}

Eigen::VectorXd derivative(const Eigen::VectorXd& v, double ts) {
  const Eigen::Index n = v.size();
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  if (n < 2) return d;
  for (Eigen::Index k = 1; k + 1 < n; ++k) d[k] = (v[k + 1] - v[k - 1]) / (2 * ts);
  d[0] = (v[1] - v[0]) / ts;
  d[n - 1] = (v[n - 1] - v[n - 2]) / ts;
  return d;
}

Eigen::VectorXd first_order_lag(const Eigen::VectorXd& v, double tau, double ts) {
  Eigen::VectorXd out(v.size());
  const double a = std::exp(-ts / tau);
  double state = v.size() ? v[0] : 0.0;
  for (Eigen::Index k = 0; k < v.size(); ++k) out[k] = state = a * state + (1 - a) * v[k];
  return out;
}

std::vector<int> branches(const Eigen::VectorXd& u) {
  const Eigen::Index n = u.size();
  std::vector<int> out(std::size_t(n), 0);
  if (n < 2) return out;
  const Eigen::VectorXd du = u.tail(n - 1) - u.head(n - 1);
  const double tol = kHoldingTolerance * du.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 1; k < n; ++k)
    out[std::size_t(k)] = du[k - 1] > tol ? 1 : (du[k - 1] < -tol ? -1 : 0);
  out[0] = out[1];
  return out;
}

Eigen::VectorXd direction_of_motion(const Eigen::VectorXd& u) {
  const auto branch = branches(u);
  Eigen::VectorXd out(u.size());
  for (std::size_t i = 0; i < branch.size(); ++i) out[Eigen::Index(i)] = branch[i];
  return out;
}

std::vector<int> amplitude_bins(const Eigen::VectorXd& u, std::vector<double>& edges) {
  const Eigen::ArrayXd a = (u.array() - (u.size() ? u.mean() : 0.0)).abs();
  const double top = a.size() ? a.maxCoeff() : 0.0;
  edges.clear();
  for (int b = 0; b <= kAmplitudeBins; ++b) edges.push_back(top * b / kAmplitudeBins);
  std::vector<int> bin(std::size_t(u.size()), 0);
  if (!(top > 0)) return bin;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    bin[std::size_t(i)] = std::min(kAmplitudeBins - 1, int(a[i] / top * kAmplitudeBins));
  return bin;
}

Eigen::VectorXd stop_operator(const Eigen::VectorXd& x, double r) {
  Eigen::VectorXd out(x.size());
  double play = x.size() ? x[0] : 0.0;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    play = std::max(x[k] - r, std::min(x[k] + r, play));
    out[k] = x[k] - play;
  }
  return out;
}

LoopCorrelation loop_correlation(const Eigen::VectorXd& e, const Eigen::VectorXd& x) {
  LoopCorrelation best{kNaN, kNaN};
  if (x.size() == 0) return best;
  const double half_range = 0.5 * (x.maxCoeff() - x.minCoeff());
  if (!(half_range > 0)) return best;
  for (double width : kLoopWidths) {
    const double r = correlation(e, stop_operator(x, width * half_range));
    if (std::isfinite(r) && !(std::abs(r) <= std::abs(best.correlation))) best = {r, width};
  }
  return best;
}

Regression regress(const Eigen::VectorXd& e, const Eigen::MatrixXd& X) {
  Regression out{kNaN, Eigen::VectorXd::Constant(X.cols(), kNaN)};
  if (e.size() <= X.cols() + 1 || X.rows() != e.size()) return out;
  const Eigen::VectorXd ec = (e.array() - e.mean()).matrix();
  const Eigen::MatrixXd Xc = X.rowwise() - X.colwise().mean();
  const double total = ec.squaredNorm();
  if (!(total > 0) || !Xc.allFinite()) return out;
  out.coefficients = Xc.colPivHouseholderQr().solve(ec);
  out.r_squared = 1.0 - (ec - Xc * out.coefficients).squaredNorm() / total;
  return out;
}

}  // namespace hystbench
