#pragma once
// One run of the feedforward vibration-control loop
// (docs/control.md#the-loop), per sample n:
//
//   x(n)  = r sin(2 pi f0 n / fs)           reference (the disturbance is known)
//   u(n)  = controller.output(x(n))
//   e*(n) = P[d_v](n) + S[u](n)             true residual at the sensor
//   e(n)  = e*(n) + v(n)                    measured, v white Gaussian (seeded)
//   x'(n) = S_hat[x](n);  controller.adapt(e(n), x'(n))
//
// with d_v(n) = a sin(2 pi f0 n / fs) into the disturbance actuator. The
// paths are copies: a run never changes the streams it was given.
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "framework/control/controller.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

struct LoopPaths {
  std::unique_ptr<SignalStream> control;      // u -> sensor, actuator included
  std::unique_ptr<SignalStream> disturbance;  // d_v -> sensor
};

struct LoopSettings {
  double sample_rate_hz = 1000.0;
  double duration_s = 60.0;
  double disturbance_hz = 20.61;
  double disturbance_amplitude = 3.0;
  double reference_amplitude = 1.0;
  double noise_sd = 0.0;  // sensor noise
  // A run has diverged once the 1 s moving RMS of the true error exceeds
  // divergence_level, or anything becomes non-finite; and also when it ends
  // above kUnsettledRatio times the uncontrolled level (an unstable loop
  // that the output limit holds in a limit cycle). 0: never checked.
  double divergence_level = 0.0;
  double uncontrolled_level = 0.0;
  static constexpr double kUnsettledRatio = 1.25;  // +1.9 dB

  long samples() const;
};

struct LoopTrace {
  std::vector<double> error;       // e(n), measured
  std::vector<double> true_error;  // e*(n)
  std::vector<double> control;     // u(n)
  std::vector<double> step;        // step size used at n
  std::vector<double> weight_norm;
  // Time (s) at which the run was found diverged, NaN if never: where it
  // was stopped (the traces end there), or where its final stretch above the
  // uncontrolled level began.
  double diverged_at_s = std::numeric_limits<double>::quiet_NaN();
  bool diverged() const;
};

// `estimate` is S_hat, x -> x'.
LoopTrace run_loop(const LoopPaths& paths, const SignalStream& estimate, Controller& controller,
                   const LoopSettings& settings, std::uint64_t noise_seed);

// The RMS of the last `window` samples ending at each sample (from the first
// full window on; earlier samples use what there is).
std::vector<double> moving_rms(const std::vector<double>& x, long window);

}  // namespace hystbench
