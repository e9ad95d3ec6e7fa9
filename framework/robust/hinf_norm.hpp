#pragma once
// The H∞ norm of a system (+inf when it is unstable), the peak gain of its frequency response,
// by SLICOT's AB13DD (Bruinsma–Steinbuch). Continuous systems peak over
// s = jω, discrete ones over z = e^{jθ} (θ in radians per sample).
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

enum class TimeDomain { Continuous, Discrete };

struct HinfNorm {
  double norm = 0.0;       // +inf for an unstable system or a pole on the axis or circle
  double frequency = 0.0;  // where it peaks: rad/s, or rad/sample; +inf at infinite frequency
};

// `tolerance`: relative accuracy, 0 <= tolerance < 1. Throws InputError
// naming SLICOT's reason when the computation fails.
HinfNorm hinf_norm(const StateSpace& system, TimeDomain domain, double tolerance = 1e-9);

}  // namespace hystbench::robust
