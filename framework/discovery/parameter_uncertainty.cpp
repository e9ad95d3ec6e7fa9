#include "framework/discovery/parameter_uncertainty.hpp"

#include "framework/core/eigen.hpp"
#include <cmath>
#include <limits>

namespace hystbench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Estimation residuals y − ŷ (normalised); false when the model is unstable.
bool residuals(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
               Eigen::VectorXd& r) {
  Eigen::VectorXd y;
  if (!model.simulate(x, data, y) || !y.allFinite()) return false;
  r = ((data.y - y).array() * data.estimation.array()).matrix();
  return true;
}

// Central differences, one-sided where a bound is too close; the step is
// 1e-5 of the parameter's range, well above rounding and below curvature.
bool jacobian(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
              Eigen::MatrixXd& J) {
  const Bounds b = model.bounds();
  J.resize(data.size(), x.size());
  Eigen::VectorXd up, down;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double h = 1e-5 * (b.upper[i] - b.lower[i]);
    Eigen::VectorXd xp = x, xm = x;
    xp[i] = std::min(x[i] + h, b.upper[i]);
    xm[i] = std::max(x[i] - h, b.lower[i]);
    if (!(xp[i] > xm[i]) || !residuals(model, xp, data, up) || !residuals(model, xm, data, down))
      return false;
    J.col(i) = -(up - down) / (xp[i] - xm[i]);  // dŷ/dx = −dr/dx
  }
  return true;
}

}  // namespace

std::pair<std::pair<int, int>, double> ParameterUncertainty::most_correlated() const {
  std::pair<int, int> best{-1, -1};
  double value = 0;
  for (Eigen::Index i = 0; i < correlation.rows(); ++i)
    for (Eigen::Index j = i + 1; j < correlation.cols(); ++j)
      if (std::isfinite(correlation(i, j)) && std::abs(correlation(i, j)) > std::abs(value))
        best = {int(i), int(j)}, value = correlation(i, j);
  return {best, value};
}

ParameterUncertainty parameter_uncertainty(const Model& model, const Eigen::VectorXd& x,
                                           const ModelData& data) {
  const Eigen::Index k = x.size();
  ParameterUncertainty u{Eigen::VectorXd::Constant(k, kNaN), Eigen::MatrixXd::Constant(k, k, kNaN)};
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  const long n = long(data.estimation_count());
  if (n <= k || !residuals(model, x, data, r) || !jacobian(model, x, data, J)) return u;
  const double s2 = r.squaredNorm() / double(n - k);
  // Scaled to unit diagonal so that the rank decision does not depend on units.
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  const Eigen::VectorXd d = JtJ.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd S = d.asDiagonal() * JtJ * d.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(S);
  const Eigen::VectorXd& lambda = eig.eigenvalues();
  const double floor = 1e-10 * lambda.maxCoeff();
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(k, k);
  Eigen::VectorXd undetermined = Eigen::VectorXd::Zero(k);
  for (Eigen::Index m = 0; m < k; ++m) {
    const Eigen::VectorXd v = eig.eigenvectors().col(m);
    if (lambda[m] > floor)
      inverse += v * v.transpose() / lambda[m];
    else
      undetermined = undetermined.cwiseMax(v.cwiseAbs());
  }
  const Eigen::MatrixXd cov = s2 * d.asDiagonal() * inverse * d.asDiagonal();
  for (Eigen::Index i = 0; i < k; ++i)
    u.sd[i] = undetermined[i] > 0.1 || JtJ(i, i) <= 0 ? kInf : std::sqrt(cov(i, i));
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j)
      if (std::isfinite(u.sd[i]) && std::isfinite(u.sd[j]) && u.sd[i] > 0 && u.sd[j] > 0)
        u.correlation(i, j) = cov(i, j) / (u.sd[i] * u.sd[j]);
  u.available = true;
  return u;
}

}  // namespace hystbench
