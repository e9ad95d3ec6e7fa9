#pragma once
// What seed 002's printed design numbers give when checked
// (docs/tracking.md#the-seeds-printed-design), and why the tracking design
// does not use them:
//
//   L(z) = (0.2146 z − 0.7352)/(z² − 1.4215 z + 1.0257)            (eq. 22)
//   K3(s) = 248.3778 (s + 1.329e4)(s + 2.227)/(s (s + 3305)(s + 174))  (eq. 27)
//   P = [0 Wr 1; −Wa 0 −L; −Wa 0 −L], Wr = 1/(z L)                 (eqs. 23, 25)
//
// at the 10 kHz rate of the seed's dSPACE loop.
#include "framework/core/eigen.hpp"
#include <string>

namespace hystbench {

struct SeedNumbersCheck {
  double sample_time = 1e-4;
  Eigen::VectorXcd l_poles, l_zeros;  // of L(z)
  double l_dc_gain = 0.0;
  // The printed K3 closing the printed L (made continuous by inverse
  // Tustin), u = −K3 y: the largest real part of the closed-loop poles;
  // then with −L (the other sign); then K3 by Tustin against L(z): the
  // spectral radius.
  double k3_max_real = 0.0, k3_max_real_other_sign = 0.0, k3_spectral_radius = 0.0;
  // SB10AD on eq. 25 built from the printed L and Wr.
  std::string eq25_printed;
  // Eq. 25 with a stable L of our choosing (1260 Hz, damping 0.6) and
  // Wr = 1/L with two 3 kHz poles: the optimal γ and the norm of the
  // closed loop with K = 0, equal when the problem is degenerate.
  double eq25_gamma_min = 0.0, eq25_norm_without_controller = 0.0;
};

SeedNumbersCheck check_seed_numbers();

}  // namespace hystbench
