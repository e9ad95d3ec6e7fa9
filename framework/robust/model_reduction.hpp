#pragma once
// Model order reduction by SLICOT: balanced truncation (AB09AD, MATLAB's
// balred; absolute error, ‖G − Gr‖∞ ≤ 2 Σ of the discarded Hankel singular
// values) and balanced stochastic truncation (AB09HD, MATLAB's bstmr;
// relative error), the method seed 002 reduces its H∞ controller with.
#include <vector>

#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

struct Reduction {
  StateSpace reduced;
  std::vector<double> hankel;  // Hankel singular values, decreasing (of the phase system for BST)
  int unstable_kept = 0;       // unstable modes kept unreduced (BST)
  // BT: ‖G − Gr‖∞ ≤ 2 Σ of the discarded values. BST: Π (1 + σ)/(1 − σ) − 1
  // over them bounds the *relative* error of the stable part, weighted by
  // the inverse of its spectral factor W (W*W = [Gs βI][Gs βI]*); times
  // ‖[Gs βI]‖∞ it bounds the absolute error of the stable part.
  double error_bound = 0.0;
};

// Reduces a stable system to `order` (1 or more) states (fewer when the system has
// fewer significant ones). Throws InputError naming SLICOT's reason.
Reduction balanced_truncation(const StateSpace& system, TimeDomain domain, int order);

// BST keeps unstable modes and reduces the stable part. `beta` > 0 weighs
// absolute against relative error: 0 is the pure relative-error method,
// which needs D of full row rank; a strictly proper controller needs
// beta > 0 (about 1e-3 of its H∞ norm).
Reduction stochastic_truncation(const StateSpace& system, TimeDomain domain, int order, double beta);

}  // namespace hystbench::robust
