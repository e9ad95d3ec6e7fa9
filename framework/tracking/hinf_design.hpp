#pragma once
// The two-degree-of-freedom H∞ design of seed 002, made well posed
// (docs/tracking.md#design): feedforward Wr = 1/(z L) (eq. 23) and a
// feedback controller from the mixed-sensitivity problem
//
//   min over stabilising K of ‖ [Wp S; Wa K S] ‖∞,   S = 1/(1 + L K),
//
// on the nominal L made continuous by the inverse Tustin map, with the
// additive-uncertainty weight Wa and the performance weight
// Wp(s) = (s/M + ωb)/(s + ωb A). γ < 1 guarantees robust stability for every
// L_true = L + Δ with |Δ| ≤ |Wa| (‖Wa K S‖∞ < 1) and |S| < 1/|Wp|.
// The full-order controller (SB10AD) is reduced by balanced stochastic
// truncation (AB09HD, MATLAB's bstmr) or balanced truncation (AB09AD), and
// both are mapped back to the loop's rate by Tustin (AB04MD).
#include <string>

#include "framework/robust/state_space.hpp"
#include "framework/tracking/nominal_dynamics.hpp"
#include "framework/tracking/uncertainty_weight.hpp"

namespace hystbench {

struct PerformanceWeight {
  double bandwidth_hz = 100.0;   // ωb = 2π bandwidth_hz
  double peak = 2.0;             // M: the largest |S| allowed
  double low_frequency_error = 1e-4;  // A: |S(0)| allowed (a pure integrator would violate SB10AD's assumptions)
  robust::StateSpace weight() const;
};

struct DesignOptions {
  PerformanceWeight performance;
  int reduced_order = 3;
  std::string reduction = "stochastic";  // or "balanced"
  double backoff = 0.05;                 // the controller is computed at (1 + backoff) γ_min
};

struct ControllerCheck {
  double norm = 0.0;            // ‖[Wp S; Wa K S]‖∞ on the nominal model (AB13DD)
  bool stable = false;          // the continuous closed loop
  bool edges_stable = false;    // the closed loop on L + Wa and on L − Wa
  double spectral_radius = 0.0; // the discrete closed loop with L(z) and the Tustin controller
};

struct ControllerDesign {
  robust::StateSpace plant;                 // generalized plant [w; u] -> [Wp e; Wa u; e]
  robust::StateSpace continuous_dynamics;   // L(s), inverse Tustin of L(z)
  robust::StateSpace full, reduced;         // continuous controllers, u = K e
  robust::StateSpace full_discrete, reduced_discrete;
  double gamma_min = 0.0, gamma = 0.0;
  ControllerCheck full_check, reduced_check;
  std::string reduction;                    // the method that gave `reduced`
  std::vector<double> hankel;               // of the reduction
  double reduction_bound = 0.0;             // the method's a-priori error bound
  double reduction_error = 0.0;             // ‖K − Kr‖∞
  double reduction_relative_error = 0.0;    // max |K − Kr|/|K| from 1 Hz to 1 kHz
};

// Throws InputError naming what failed (the plant's assumptions, SLICOT's reason).
ControllerDesign design_controller(const NominalDynamics& nominal, const UncertaintyWeight& wa,
                                   const DesignOptions& options);
// The reference of the tests and of the fixed-order problem: L(s) a 1260 Hz
// resonance of damping 0.6 (a piezo stack's first mode), designed with seed
// 002's Wa at 10 kHz, L(z) its zero-order hold. With the default options:
// γ_min 0.50984, the full controller's norm 0.52204, the 3rd-order one's 0.52454.
robust::StateSpace reference_dynamics();
ControllerDesign reference_design(const DesignOptions& options = {});

// The same from a continuous L(s), the loop still checked on L(z) at `sample_time`.
ControllerDesign design_controller(const robust::StateSpace& continuous_dynamics,
                                   const robust::StateSpace& discrete_dynamics, double sample_time,
                                   const UncertaintyWeight& wa, const DesignOptions& options);

}  // namespace hystbench
