#pragma once
// Stage 2 of the SVR Hammerstein-like model (docs/svr.md#stage-2): a linear
// ARX block from v to y,
//
//   y(k) = -a_1 y(k-1) - ... - a_p y(k-p) + b_0 v(k) + ... + b_{q-1} v(k-q+1) + e(k),
//
// fitted by least squares on the equation error (measured y in the
// regressors), its orders chosen by AIC(p, q) = N ln(V_N) + 2 (p + q) over a
// grid (V_N the mean squared equation error over the same N samples for
// every order), fits whose A(z) has a root on or outside the unit circle
// rejected.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

struct ArxFit {
  int p = 0, q = 0;
  Eigen::VectorXd a;  // a_1 .. a_p
  Eigen::VectorXd b;  // b_0 .. b_{q-1}
  double mean_squared_error = 0.0;  // V_N
  double aic = 0.0;
  bool stable = false;  // every root of A(z) strictly inside the unit circle

  // Output-error simulation from rest: y_hat driven by v and its own past.
  Eigen::VectorXd simulate(const Eigen::VectorXd& v) const;
};

// Least squares for fixed orders, on samples k = skip .. N-1 (skip at least
// max(p, q - 1)). Throws InputError naming `where` when there are fewer
// samples than coefficients.
ArxFit fit_arx(const Eigen::VectorXd& v, const Eigen::VectorXd& y, int p, int q, int skip,
               const std::string& where);

struct ArxSelection {
  std::vector<ArxFit> grid;  // every (p, q), p and q in 1..max
  ArxFit best;               // the stable fit of least AIC
};

// Throws InputError naming `where` when no order gives a stable fit.
ArxSelection select_arx(const Eigen::VectorXd& v, const Eigen::VectorXd& y, int p_max, int q_max,
                        const std::string& where);

}  // namespace hystbench
