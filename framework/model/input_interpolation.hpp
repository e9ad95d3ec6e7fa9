#pragma once
// Interpolation of a sampled input between its samples, for effects that
// integrate an ODE with several internal steps per sample.
//
// A not-a-knot cubic spline through evenly spaced samples: exact for cubic
// polynomials, and about two orders of magnitude closer to a band-limited
// input than linear interpolation (holding the input constant over a sample
// is worse still). Positions are in samples: sample k sits at position k.
#include "framework/core/eigen.hpp"

namespace hystbench {

class UniformCubicSpline {
 public:
  UniformCubicSpline() = default;
  explicit UniformCubicSpline(const Eigen::Ref<const Eigen::VectorXd>& samples) { fit(samples); }

  // Recomputes the spline for new samples (reuses the storage).
  void fit(const Eigen::Ref<const Eigen::VectorXd>& samples);

  Eigen::Index size() const { return w_.size(); }
  // Second derivative at each sample, per sample².
  const Eigen::VectorXd& second_derivatives() const { return m_; }

  // Weights of w[k], w[k+1], M[k], M[k+1] for the value at position k + s,
  // 0 <= s <= 1 (the same for every interval, so a caller evaluating many
  // intervals at the same fractions computes them once).
  struct Weights {
    double w0, w1, m0, m1;
  };
  static Weights weights(double s);

  // Value at position k + s with the precomputed weights of s.
  double value(Eigen::Index k, const Weights& c) const {
    if (k + 1 >= size()) return w_[size() - 1];
    return c.w0 * w_[k] + c.w1 * w_[k + 1] + c.m0 * m_[k] + c.m1 * m_[k + 1];
  }
  // Value at `position` (in samples), held constant outside [0, size-1].
  double operator()(double position) const;

 private:
  Eigen::VectorXd w_;
  Eigen::VectorXd m_;
  Eigen::VectorXd scratch_;
};

}  // namespace hystbench
