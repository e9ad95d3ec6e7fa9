#pragma once
// H∞ controller synthesis for a continuous generalized plant, MATLAB's
// hinfsyn, by SLICOT's SB10AD (Glover–Doyle formulae with γ iteration).
//
// The plant maps [w; u] to [z; y]: the last `ncon` inputs are the control
// u, the last `nmeas` outputs the measurement y. The controller closes the
// loop as u = K y (positive feedback, SLICOT's convention) and makes the
// H∞ norm of the closed loop from w to z at most γ.
//
// Pitfalls handled here: the γ search starts at a finite `gamma_max` (a
// search from 1e100 never returns when no controller exists); the
// controller is recomputed at (1 + backoff) times the γ found, because the
// controller at the optimum has entries near 1e14 and a loop SB10AD calls
// stable may not be; the rank and stabilizability assumptions are checked
// before SB10AD runs, so their failures are messages that name them.
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

struct HinfOptions {
  double gamma_max = 1e4;   // start of the search: an admissible γ must lie below it
  double gamma_tol = 1e-4;  // accuracy of γ (SB10AD's GTOL)
  double backoff = 0.01;    // the returned controller is computed at (1 + backoff) γ_min
  // Fixed γ instead of a search (SB10AD JOB = 4): 0 searches.
  double fixed_gamma = 0.0;
};

struct HinfController {
  StateSpace controller;   // K, states as many as the plant's
  StateSpace closed_loop;  // from w to z
  double gamma_min = 0.0;  // the least γ the search found admissible (the fixed γ without a search)
  double gamma = 0.0;      // the γ the controller was computed at
  double rcond[4] = {0, 0, 0, 0};  // control and measurement transformations, X and Y Riccati
};

// Throws InputError naming the failed assumption (or the bad size).
HinfController hinf_synthesis(const StateSpace& plant, int nmeas, int ncon, const HinfOptions& options = {});

}  // namespace hystbench::robust
