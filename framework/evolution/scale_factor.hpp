#pragma once
// Scale-factor (F) rules of the DE variants: DETVSF and DERSF
// (docs/algorithms.md#detvsf-and-dersf), MEDE (docs/algorithms.md#mede) and
// AmFMMDE's adaptive rules AMF-1..3 (docs/algorithms.md#adaptive-scale-factor).
//
// Pure functions: a random rule takes its U(0,1) draw `u` as an argument, so
// each rule can be checked by hand and the caller decides when to draw.
// tau is the progress ratio nfe / MaxFEs in [0, 1].

namespace hystbench {

// DETVSF with the erratum resolved (docs/algorithms.md#detvsf), also AMF-2:
// F = f_max - (f_max - f_min) tau, from f_max at tau = 0 to f_min at tau = 1.
double time_varying_scale_factor(double f_min, double f_max, double tau);

// DERSF (docs/algorithms.md#dersf): F = 0.5 (1 + u), uniform in [0.5, 1).
double random_scale_factor(double u);

// MEDE eq. 16 (docs/algorithms.md#mede): F = f_min + u (f_max - f_min).
double uniform_scale_factor(double f_min, double f_max, double u);

// AMF-1 (docs/algorithms.md#adaptive-scale-factor, RECONSTRUCTION):
// F = f_min + (f_max - f_min) u (1 - tau);
// MEDE's rule at tau = 0, shrinking to f_min at tau = 1.
double amf1_scale_factor(double f_min, double f_max, double u, double tau);

// AMF-3 (docs/algorithms.md#adaptive-scale-factor, RECONSTRUCTION):
// F = f0 2^lambda with lambda = exp(1 - 1 / (1 + 1/G_max - tau)); `inverse_gmax` is 1/G_max (0 for
// the limit of many generations). About 2 f0 at tau = 0, f0 at tau = 1.
double amf3_scale_factor(double f0, double tau, double inverse_gmax);

}  // namespace hystbench
