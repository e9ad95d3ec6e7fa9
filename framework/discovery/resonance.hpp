#pragma once
// Where each dynamics effect of a fitted model resonates, found from the
// effect alone: its response to a small impulse, evaluated on a logarithmic
// frequency grid. Two dynamics effects that resonate at the same frequency
// describe one mode twice: a "second mode" fitted onto the first mode's
// resonance takes over that effect's role instead of adding a mode. Found
// for any effect of the dynamics stage, a user's own included.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/model/model.hpp"

namespace hystbench {

struct Resonance {
  std::string effect;
  double hz = 0.0;           // frequency of the largest gain
  double peak_gain = 0.0;    // largest gain over the gain at the lowest frequency
};

// Dynamics effects of `model` whose gain peaks at least 1.2 times above
// their low-frequency gain.
std::vector<Resonance> resonances(const Model& model, const Eigen::VectorXd& x,
                                  double sample_time);

// "second_mode resonates at 40.1 Hz, as msd does (40.0 Hz): ..." when
// `effect` shares its resonance (within 10 %) with another dynamics effect
// of the model; "" otherwise.
std::string shared_resonance(const Model& model, const Eigen::VectorXd& x, double sample_time,
                             const std::string& effect);

}  // namespace hystbench
