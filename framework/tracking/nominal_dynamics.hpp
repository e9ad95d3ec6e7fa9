#pragma once
// The linear part L(z) a tracking controller is designed on
// (docs/tracking.md#nominal-model): the identified model's back (dynamics
// and output stages) as the loop sees it, one sample late because the
// input computed at sample k is applied from sample k + 1, identified as
// an ARX model from a reproducible random input at the loop's rate, and the
// feedforward Wr = 1/(z L) of seed 002's eq. 23 (L Wr = z⁻¹).
#include <cstdint>
#include <string>
#include <vector>

#include "framework/tracking/identified_model.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench {

struct NominalDynamics {
  // L(z) = num/den, highest power of z first, strictly proper.
  std::vector<double> num, den;
  robust::StateSpace discrete;     // L(z)
  robust::StateSpace feedforward;  // Wr(z) = 1/(z L(z)), proper
  double sample_time = 0.0;
  int p = 0, q = 0;
  // Output-error RMS of L against the back, relative to the back's output
  // RMS: near 0 when the back is linear of order (p, q) or less.
  double misfit = 0.0;
};

// Throws InputError naming `where` when the ARX fit is unstable or L has a
// zero on or outside the unit circle (Wr would then be unstable).
NominalDynamics identify_dynamics(const IdentifiedModel& model, double sample_time, int p, int q,
                                  std::uint64_t seed, const std::string& where);

// L and Wr from a given L(z) (seed 002's printed one, a test's): the same
// checks.
NominalDynamics nominal_from_transfer(std::vector<double> num, std::vector<double> den, double sample_time,
                                      const std::string& where);

}  // namespace hystbench
