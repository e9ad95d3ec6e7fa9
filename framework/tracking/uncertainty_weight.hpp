#pragma once
// The additive-uncertainty weight Wa of the design (docs/tracking.md#uncertainty):
// |L_true(jω) − L(jω)| ≤ |Wa(jω)| is what the controller must tolerate.
//
// Seed 002 (eq. 21, Fig. 6) bounds the spread of its identified linear
// parts over operating points. Here the bound comes from the identification
// residual: on every excitation segment of the given records, the first
// harmonic of the residual y − ŷ relative to that of the front output ŵ at
// the segment's dominant frequency is one point of |ΔL|. The weight
//
//   Wa(s) = k∞ (s + ωc k0/k∞)/(s + ωc)
//
// has k0 = margin × the largest point, so it bounds every point, and rises
// from k0 below ωc/rise to k∞ = rise × k0 above ωc, the highest measured
// frequency: towards and beyond the edge of the measured band the model is
// trusted less, as the seed's Wa rises from 0.020 to 0.077.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/tracking/identified_model.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench {

struct UncertaintyPoint {
  std::string record, segment;
  double hz = 0.0;
  double bound = 0.0;  // |E(f)| / |Ŵ(f)|
};

struct UncertaintyWeight {
  std::string source;  // "seed 002, eq. 21" or "identification residual"
  std::vector<double> num, den;  // Wa(s), highest power first
  robust::StateSpace weight;
  std::vector<UncertaintyPoint> points;
  double margin = 0.0, rise = 0.0;
};

// Wa(s) = −0.07652 (s + 3.412)(s + 46.25) / ((s + 78.61)(s + 7.846)).
UncertaintyWeight seed_uncertainty_weight();

// A weight the experiment gives, in s. Throws InputError naming `where`
// when it is not proper or not stable.
UncertaintyWeight given_uncertainty_weight(const std::vector<double>& num, const std::vector<double>& den,
                                           const std::string& where);

// Throws InputError naming `where` when a record cannot be read or no
// segment has a usable dominant frequency.
UncertaintyWeight residual_uncertainty_weight(const IdentifiedSource& model,
                                              const std::vector<std::filesystem::path>& records,
                                              double margin, double rise, const std::string& where);

}  // namespace hystbench
