#pragma once
// Correlation tests of a residual e = y − ŷ (Ljung, System Identification,
// 1999; MATLAB `resid` conventions).
//
//   r_ee(τ) = Σ_k ẽ_k ẽ_{k−τ} / Σ_k ẽ_k²                       τ = 1..L
//   r_ue(τ) = Σ_k ũ_{k−τ} ẽ_k / √(Σ ũ² · Σ ẽ²)                τ = −L..L
// with ẽ, ũ the mean-removed signals and sums over the samples where both
// indices exist. τ > 0 in r_ue pairs the residual with *past* input: a
// residual that is the input delayed by d samples peaks at τ = d.
// The 99 % band of a white residual is ±2.58/√N per lag.
//
// Ljung–Box: Q(h) = N(N+2) Σ_{τ=1..h} r_ee(τ)²/(N−τ), χ²(h) under whiteness.
#include "framework/core/eigen.hpp"
#include <vector>

namespace hystbench {

struct Correlation {
  std::vector<int> lags;
  std::vector<double> values;  // NaN when a signal is constant (no spread)
  double bound = 0;            // 2.58/√N
  int outside = 0;             // lags with |value| > bound
};

// Autocorrelation at lags 1..max_lag.
Correlation autocorrelation(const Eigen::VectorXd& e, int max_lag);
// Input–residual cross-correlation at lags −max_lag..max_lag.
Correlation cross_correlation(const Eigen::VectorXd& u, const Eigen::VectorXd& e, int max_lag);
// Lag of the largest |value| (0 when all are NaN).
int peak_lag(const Correlation& c);

struct LjungBox {
  int lags = 0;
  double q = 0, p_value = 1;
};
// h = min(max_lags, N/5), at least 1; p from the χ²(h) survival function.
// A constant residual (or N < 2) has Q = 0, p = 1; a non-finite one NaN.
LjungBox ljung_box(const Eigen::VectorXd& e, int max_lags = 20);

}  // namespace hystbench
