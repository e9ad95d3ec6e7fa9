#pragma once
// Signals a residual is tested against: each effect's signature statistic
// (residual_signature.hpp) correlates the residual e = y − ŷ with the shape
// the effect would leave in it, built from these pieces. The breakdown
// tables of `compare` use the same branches and amplitude bins.
#include "framework/core/eigen.hpp"
#include <vector>

namespace hystbench {

constexpr int kAmplitudeBins = 5;
constexpr double kHoldingTolerance = 1e-3;  // of max |Δu|

// Pearson correlation; NaN when either signal is constant or n < 2.
double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

// Sample standard deviation (n − 1); NaN for n < 2.
double standard_deviation(const Eigen::VectorXd& v);

// Central differences divided by 2·Ts (one-sided at the ends).
Eigen::VectorXd derivative(const Eigen::VectorXd& v, double sample_time);

// v through the first-order lag x[k] = a·x[k−1] + (1 − a)·v[k], a = exp(−Ts/tau),
// starting at x[−1] = v[0].
Eigen::VectorXd first_order_lag(const Eigen::VectorXd& v, double tau, double sample_time);

// Branch of every sample: +1 loading (Δu > tol), −1 unloading (Δu < −tol),
// 0 holding, Δu_k = u_k − u_{k−1}, tol = kHoldingTolerance · max |Δu|; the first
// sample takes the branch of the second.
std::vector<int> branches(const Eigen::VectorXd& u);
// The same as a signal: sign(Δu), the direction of motion.
Eigen::VectorXd direction_of_motion(const Eigen::VectorXd& u);

// Amplitude bin (0..kAmplitudeBins−1) of every sample, and the bin edges
// of |u − mean(u)| (kAmplitudeBins + 1 equal-width values).
std::vector<int> amplitude_bins(const Eigen::VectorXd& u, std::vector<double>& edges);

// The stop operator x − play_r(x) (Krasnosel'skii & Pokrovskii, Systems with
// Hysteresis, 1989): play F[k] = max(x[k] − r, min(x[k] + r, F[k−1])), F[−1] = x[0].
// A rate-independent loop of half-height r that switches over a stroke of 2r
// after every reversal; sums of them make Prandtl–Ishlinskii hysteresis.
Eigen::VectorXd stop_operator(const Eigen::VectorXd& x, double r);

struct LoopCorrelation {
  double correlation = 0.0;  // corr(e, stop_r(x)) at the best width; NaN if undefined
  double width = 0.0;        // that r as a share of x's half range (max − min)/2
};
// corr(e, stop_r(x)) over the widths r = 1/16, 1/8, 1/4, 1/2 of x's half range;
// the one of largest magnitude. The loop's width is not known in advance.
LoopCorrelation loop_correlation(const Eigen::VectorXd& e, const Eigen::VectorXd& x);

struct Regression {
  double r_squared = 0.0;             // share of var(e) explained; NaN when undefined
  Eigen::VectorXd coefficients = {};  // one per column of X (after mean removal)
};
// Least squares e ≈ c0 + X·c: the share of the variance of e it explains.
Regression regress(const Eigen::VectorXd& e, const Eigen::MatrixXd& X);

}  // namespace hystbench
