#pragma once
// Continuous ↔ discrete by the bilinear (Tustin) map s = (2/Ts)(z − 1)/(z + 1),
// SLICOT's AB04MD. The transfer function is Tustin's; the state basis is
// SLICOT's symmetric one (B and C both scaled by √Ts), not the textbook's.
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

// Throws InputError when Ts is not positive or A has an eigenvalue at 2/Ts.
StateSpace tustin(const StateSpace& continuous, double sample_time);
// The inverse map (A must have no eigenvalue at −1).
StateSpace inverse_tustin(const StateSpace& discrete, double sample_time);

}  // namespace hystbench::robust
