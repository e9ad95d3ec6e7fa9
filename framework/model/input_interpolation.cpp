#include "framework/model/input_interpolation.hpp"

#include <cmath>

namespace hystbench {

void UniformCubicSpline::fit(const Eigen::Ref<const Eigen::VectorXd>& samples) {
  w_ = samples;
  const Eigen::Index n = w_.size();
  m_.setZero(n);
  if (n < 3) return;  // constant or linear
  if (n == 3) {       // the parabola through the three points
    m_.setConstant(w_[0] - 2.0 * w_[1] + w_[2]);
    return;
  }
  // Unit spacing: M[i-1] + 4 M[i] + M[i+1] = 6 d[i], d[i] = w[i-1] - 2 w[i] + w[i+1],
  // for i = 1..n-2. Not-a-knot (third derivative continuous at samples 1 and
  // n-2) gives M[0] = 2 M[1] - M[2], which turns the first equation into
  // M[1] = d[1]; likewise M[n-2] = d[n-2] at the other end.
  const Eigen::Index last = n - 2;
  auto d = [&](Eigen::Index i) { return w_[i - 1] - 2.0 * w_[i] + w_[i + 1]; };
  scratch_.resize(n);  // modified super-diagonal of the Thomas algorithm
  // Row 1: diagonal 1, super-diagonal 0, right-hand side d[1].
  scratch_[1] = 0.0;
  m_[1] = d(1);
  for (Eigen::Index i = 2; i <= last; ++i) {
    const bool end = i == last;
    const double sub = end ? 0.0 : 1.0;
    const double diag = end ? 1.0 : 4.0;
    const double sup = end ? 0.0 : 1.0;
    const double rhs = end ? d(i) : 6.0 * d(i);
    const double denom = diag - sub * scratch_[i - 1];
    scratch_[i] = sup / denom;
    m_[i] = (rhs - sub * m_[i - 1]) / denom;
  }
  for (Eigen::Index i = last - 1; i >= 1; --i) m_[i] -= scratch_[i] * m_[i + 1];
  m_[0] = 2.0 * m_[1] - m_[2];
  m_[n - 1] = 2.0 * m_[n - 2] - m_[n - 3];
}

UniformCubicSpline::Weights UniformCubicSpline::weights(double s) {
  const double r = 1.0 - s;
  return {r, s, (r * r * r - r) / 6.0, (s * s * s - s) / 6.0};
}

double UniformCubicSpline::operator()(double position) const {
  const Eigen::Index n = size();
  if (n == 0) return 0.0;
  if (!(position > 0.0)) return w_[0];
  if (position >= double(n - 1)) return w_[n - 1];
  const auto k = static_cast<Eigen::Index>(std::floor(position));
  return value(k, weights(position - double(k)));
}

}  // namespace hystbench
