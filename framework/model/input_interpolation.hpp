#pragma once
// Interpolation of a sampled input between its samples, for effects that
// integrate an ODE with several internal steps per sample.
//
// A not-a-knot cubic spline through evenly spaced samples: exact for cubic
// polynomials, and about two orders of magnitude closer to a band-limited
// input than linear interpolation (holding the input constant over a sample
// is worse still). Positions are in samples: sample k sits at position k.
#include <cstddef>
#include <span>
#include <vector>

#include "framework/core/eigen.hpp"

namespace hystbench {

// The second derivatives m (per sample²) of the not-a-knot spline through
// the evenly spaced samples w, for any element type with double arithmetic:
// a vector of several records' samples (a block of candidates) gets in each
// lane exactly what a double gets. `super` is scratch (the Thomas
// algorithm's modified super-diagonal, the same for every record of w's
// length).
template <class V>
void spline_second_derivatives(std::span<const V> w, std::span<V> m, std::vector<double>& super) {
  const std::size_t n = w.size();
  if (n < 3) {  // constant or linear
    for (auto& v : m) v = V{} + 0.0;
    return;
  }
  const auto d = [&](std::size_t i) { return w[i - 1] - 2.0 * w[i] + w[i + 1]; };
  if (n == 3) {  // the parabola through the three points
    for (auto& v : m) v = d(1);
    return;
  }
  // Unit spacing: M[i-1] + 4 M[i] + M[i+1] = 6 d[i], d[i] = w[i-1] - 2 w[i] + w[i+1],
  // for i = 1..n-2. Not-a-knot (third derivative continuous at samples 1 and
  // n-2) gives M[0] = 2 M[1] - M[2], which turns the first equation into
  // M[1] = d[1]; likewise M[n-2] = d[n-2] at the other end.
  const std::size_t last = n - 2;
  super.resize(n);
  // Row 1: diagonal 1, super-diagonal 0, right-hand side d[1].
  super[1] = 0.0;
  m[1] = d(1);
  for (std::size_t i = 2; i <= last; ++i) {
    const bool end = i == last;
    const double sub = end ? 0.0 : 1.0;
    const double diag = end ? 1.0 : 4.0;
    const double sup = end ? 0.0 : 1.0;
    const V rhs = end ? d(i) : 6.0 * d(i);
    const double denom = diag - sub * super[i - 1];
    super[i] = sup / denom;
    m[i] = (rhs - sub * m[i - 1]) / denom;
  }
  for (std::size_t i = last - 1; i >= 1; --i) m[i] -= super[i] * m[i + 1];
  m[0] = 2.0 * m[1] - m[2];
  m[n - 1] = 2.0 * m[n - 2] - m[n - 3];
}

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
    return blend(c, w_[k], w_[k + 1], m_[k], m_[k + 1]);
  }
  // The value between samples w0 and w1 with second derivatives m0 and m1,
  // for any element type: a lane of a vector gets exactly what a double gets.
  template <class V>
  static V blend(const Weights& c, V w0, V w1, V m0, V m1) {
    return c.w0 * w0 + c.w1 * w1 + c.m0 * m0 + c.m1 * m1;
  }
  // Value at `position` (in samples), held constant outside [0, size-1].
  double operator()(double position) const;

 private:
  Eigen::VectorXd w_;
  Eigen::VectorXd m_;
  std::vector<double> scratch_;
};

}  // namespace hystbench
