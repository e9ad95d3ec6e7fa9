#pragma once
// The generalized plant of a mixed-sensitivity H∞ design (MATLAB's augw,
// python-control's augw): for a plant G and weights W1 (on the error, i.e.
// on S), W2 (on the control, i.e. on K S) and W3 (on the output, i.e. on T),
//
//   inputs  [w; u],  outputs [z1; z2; z3; v],
//   z1 = W1 (w − G u),  z2 = W2 u,  z3 = W3 G u,  v = w − G u,
//
// so that hinf_synthesis(P, outputs of G, inputs of G) minimises
// ‖[W1 S; W2 K S; W3 T]‖∞ with u = K v. A weight left out drops its z.
#include <optional>

#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

struct SensitivityWeights {
  std::optional<StateSpace> on_error;    // W1: outputs of G in and out
  std::optional<StateSpace> on_control;  // W2: inputs of G in and out
  std::optional<StateSpace> on_output;   // W3: outputs of G in and out
};

// Throws InputError when a weight's sizes do not fit G or no weight is given.
StateSpace mixed_sensitivity_plant(const StateSpace& plant, const SensitivityWeights& weights);

}  // namespace hystbench::robust
