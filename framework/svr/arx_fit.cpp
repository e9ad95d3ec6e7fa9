#include "framework/svr/arx_fit.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

// Roots of z^p + a_1 z^(p-1) + ... + a_p are the eigenvalues of its companion matrix.
bool inside_unit_circle(const Eigen::VectorXd& a) {
  const Eigen::Index p = a.size();
  if (p == 0) return true;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(p, p);
  companion.row(0) = -a.transpose();
  for (Eigen::Index i = 1; i < p; ++i) companion(i, i - 1) = 1.0;
  const Eigen::VectorXcd roots = companion.eigenvalues();
  return (roots.array().abs() < 1.0).all();
}

}  // namespace

Eigen::VectorXd ArxFit::simulate(const Eigen::VectorXd& v) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(v.size());
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    double s = 0.0;
    for (int i = 1; i <= p && k - i >= 0; ++i) s -= a[i - 1] * y[k - i];
    for (int j = 0; j < q && k - j >= 0; ++j) s += b[j] * v[k - j];
    y[k] = s;
  }
  return y;
}

ArxFit fit_arx(const Eigen::VectorXd& v, const Eigen::VectorXd& y, int p, int q, int skip,
               const std::string& where) {
  const Eigen::Index n = y.size() - skip;
  if (v.size() != y.size() || n < p + q)
    throw InputError(where + ": ARX(" + std::to_string(p) + ", " + std::to_string(q) + ") needs at least " +
                     std::to_string(p + q + skip) + " samples of v and y, got " +
                     std::to_string(v.size()) + " and " + std::to_string(y.size()));
  Eigen::MatrixXd phi(n, p + q);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Eigen::Index k = r + skip;
    for (int i = 1; i <= p; ++i) phi(r, i - 1) = -y[k - i];
    for (int j = 0; j < q; ++j) phi(r, p + j) = v[k - j];
  }
  const Eigen::VectorXd target = y.tail(n);
  const Eigen::VectorXd theta = phi.colPivHouseholderQr().solve(target);
  ArxFit f;
  f.p = p;
  f.q = q;
  f.a = theta.head(p);
  f.b = theta.tail(q);
  f.mean_squared_error = (target - phi * theta).squaredNorm() / double(n);
  f.aic = double(n) * std::log(f.mean_squared_error) + 2.0 * (p + q);
  f.stable = inside_unit_circle(f.a);
  return f;
}

ArxSelection select_arx(const Eigen::VectorXd& v, const Eigen::VectorXd& y, int p_max, int q_max,
                        const std::string& where) {
  // The same samples for every order, so the AICs compare.
  const int skip = std::max(p_max, q_max - 1);
  ArxSelection s;
  const ArxFit* best = nullptr;
  for (int p = 1; p <= p_max; ++p)
    for (int q = 1; q <= q_max; ++q) s.grid.push_back(fit_arx(v, y, p, q, skip, where));
  for (const ArxFit& f : s.grid)
    if (f.stable && (!best || f.aic < best->aic)) best = &f;
  if (!best)
    throw InputError(where + ": no ARX order up to (" + std::to_string(p_max) + ", " +
                     std::to_string(q_max) + ") gives a stable A(z); the data may not come from a "
                     "stable linear block");
  s.best = *best;
  return s;
}

}  // namespace hystbench
