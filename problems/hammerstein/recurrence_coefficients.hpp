#pragma once
// The per-candidate constants of the seed model's recurrences, computed once
// per simulation. The scalar and the batched kernels both take them from
// here, so that they multiply by bit-identical numbers.
#include "problems/hammerstein/hammerstein_model.hpp"

namespace hystbench {

// Bilinear mass-spring-damper recursion
// r[k] = -(f1 r[k-1] + g1 r[k-2] - e h1[k] - f h1[k-1] - g h1[k-2]) / e1.
struct MsdCoefficients {
  double e, f, g, e1, f1, g1;
  MsdCoefficients(const HammersteinParams& p, double Ts);
};

// The recurrences with the MSD coefficients normalised by e1:
//   h[k]  = (h[k-1] (1 - beta |drive|) + aL drive) - gamma drive |h[k-1]|
//   h1[k] = d1 u[k] + d2 u[k] u[k] - h[k]
//   r[k]  = (k_h0 h1[k] + k_h1 h1[k-1] + k_h2 h1[k-2] + k_r2 r[k-2]) + k_r1 r[k-1]
//   r1[k] = (a r[k-1] + b r[k-2] - d r1[k-2]) - c r1[k-1]
struct RecurrenceCoefficients {
  double beta, aL, gamma;
  double d1, d2;
  double k_h0, k_h1, k_h2, k_r1, k_r2;
  double a, b, c, d;

  RecurrenceCoefficients(const HammersteinParams& p, double Ts);
};

}  // namespace hystbench
