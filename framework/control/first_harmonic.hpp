#pragma once
// The first-harmonic response of a stream to a sine (docs/control.md#phase-error):
// the stream is driven from rest by amplitude sin(2 pi f n / fs) for
// `settle_s`, then the output is correlated with the sine and cosine over
// the whole number of periods that fits in the next `window_s`. For a
// linear stream this is its frequency response; for a nonlinear one, the
// describing-function gain at that amplitude.
#include <complex>

#include "framework/control/control_loop.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

struct HarmonicProbe {
  double hz = 20.61;
  double amplitude = 1.0;
  double sample_rate_hz = 1000.0;
  double settle_s = 60.0;  // lightly damped paths ring for seconds
  double window_s = 10.0;
};

// The probe at a loop's disturbance frequency and sampling rate.
HarmonicProbe probe_at(const LoopSettings& loop, double amplitude);

// Output first harmonic relative to the input sine: magnitude and phase
// (radians, negative for a lag). Resets the stream before and after.
std::complex<double> first_harmonic(SignalStream& stream, const HarmonicProbe& probe);

}  // namespace hystbench
