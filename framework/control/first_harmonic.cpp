#include "framework/control/first_harmonic.hpp"

#include <algorithm>
#include <cmath>

namespace hystbench {

HarmonicProbe probe_at(const LoopSettings& loop, double amplitude) {
  HarmonicProbe p;
  p.hz = loop.disturbance_hz;
  p.amplitude = amplitude;
  p.sample_rate_hz = loop.sample_rate_hz;
  return p;
}

std::complex<double> first_harmonic(SignalStream& stream, const HarmonicProbe& p) {
  const double w = 2.0 * M_PI * p.hz / p.sample_rate_hz;  // rad per sample
  const long settle = std::lround(p.settle_s * p.sample_rate_hz);
  const double periods = std::max(1.0, std::floor(p.window_s * p.hz));
  const long window = std::lround(periods * p.sample_rate_hz / p.hz);
  stream.reset();
  for (long n = 0; n < settle; ++n) stream.step(p.amplitude * std::sin(w * n));
  double in_phase = 0.0, quadrature = 0.0;
  for (long n = settle; n < settle + window; ++n) {
    const double y = stream.step(p.amplitude * std::sin(w * n));
    in_phase += y * std::sin(w * n);
    quadrature += y * std::cos(w * n);
  }
  stream.reset();
  // y ~ |G| A sin(wn + phi) = |G| A (cos phi sin wn + sin phi cos wn).
  return std::complex<double>(in_phase, quadrature) * (2.0 / (window * p.amplitude));
}

}  // namespace hystbench
