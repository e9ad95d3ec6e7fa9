#pragma once
// One tracking run, sample by sample at the loop's rate
// (docs/tracking.md#the-loop). At sample k:
//
//   y_k = the plant's output from the inputs up to u_{k−1} (the input
//         computed at k is applied from k + 1), plus sensor noise,
//         rounded to the sensor's resolution;
//   e_k = r_k − y_k;
//   w*  = feedforward(r_k) + feedback(e_k);
//   u_k = the inverse of the identified front at w*, within the
//         amplifier's range [u_min, u_max].
//
// The reference fades in over the first tenth of a second, or half the
// settling time when that is shorter (a raised cosine from 0): the actuator starts at rest, and a step to the
// reference's first value would saturate the amplifier and wind up the
// controllers before the scored window begins.
//
// The feedforward is Wr = 1/(z L) for the H∞ and inverse-only controllers
// and r itself for the PI; the feedback is the discretised H∞ controller,
// a PI (its integrator held on the sample after one the inverse
// saturated) or nothing. A run whose controller output stops being finite
// ends there, marked not finite, its scores NaN.
#include "framework/core/eigen.hpp"
#include <cstdint>
#include <memory>
#include <string>

#include "framework/model/signal_stream.hpp"
#include "framework/robust/state_space.hpp"
#include "framework/tracking/inverse_compensator.hpp"
#include "framework/tracking/tracking_reference.hpp"

namespace hystbench {

struct TrackingController {
  enum class Kind { InverseOnly, Hinf, Pi };
  std::string label;
  Kind kind = Kind::InverseOnly;
  std::string order;             // H∞: "full" or "reduced"
  robust::StateSpace feedback;   // H∞: the discrete controller
  double kp = 0.0, ki = 0.0;     // PI: w* = r + kp e + ki Σ e Ts
};

struct SensorSettings {
  double noise_sd = 0.0;
  double resolution = 0.0;  // 0: not rounded
};

// What every run shares; the streams are copied into each run.
struct TrackingSetup {
  double sample_time = 1e-4;
  const SignalStream* plant = nullptr;           // physical units
  const InverseCompensator* inverse = nullptr;
  const robust::StateSpace* feedforward = nullptr;  // Wr(z)
  SensorSettings sensor;
};

struct TrackingRun {
  TrackingScore score;
  InverseStatistics inverse;
  long saturated_in_window = 0;  // samples of the scored window the amplifier limited
  WindowSamples window;
  Eigen::VectorXd r, y, u;  // every sample of the run (unset after a divergence)
  bool finite = true;       // false when the loop diverged (the scores are then NaN)
};

// Runs until the end of the score window.
TrackingRun run_tracking(const TrackingSetup& setup, const TrackingController& controller,
                         const TrackingReference& reference, const ScoreWindow& window, std::uint64_t seed);

}  // namespace hystbench
