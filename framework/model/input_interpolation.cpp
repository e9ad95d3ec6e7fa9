#include "framework/model/input_interpolation.hpp"

#include <cmath>

namespace hystbench {

void UniformCubicSpline::fit(const Eigen::Ref<const Eigen::VectorXd>& samples) {
  w_ = samples;
  m_.resize(w_.size());
  spline_second_derivatives<double>({w_.data(), std::size_t(w_.size())}, {m_.data(), std::size_t(m_.size())},
                                    scratch_);
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
