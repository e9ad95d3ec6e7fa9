#pragma once
// Band-limited interpolation of a sampled input between its samples, for
// effects that integrate an ODE with several internal steps per sample
// (the `bandlimited` input hold, input_hold.hpp).
//
// A measured input is band-limited: it was generated below the Nyquist
// frequency (a multisine, filtered noise) and sampled behind an anti-alias
// filter. Between its samples it is then the sinc interpolation of them
// (Shannon). A cubic spline is exact for cubics only: between the samples
// of a sine at 0.2 of the sample rate it errs by 0.9 % of the amplitude, at
// 0.3 by 6.8 %, and an oscillator driven there turns that into a systematic
// output error (on Silverbox, docs/discovery.md, "Measured benchmarks").
//
// The kernel is a sinc windowed by a Kaiser window (β = 10) over kHalfWidth
// samples on each side, its weights scaled to sum to one so that a constant
// input stays exactly constant. Between the samples of a sine it errs by at
// most 1.3e-5 of the amplitude at any frequency up to 0.35 of the sample
// rate, below the spline's error at every frequency from 0.05 up (16
// samples a side and β = 12 reach 2e-6; 8 and β = 8, 1.6e-4 at 0.3).
// Positions are in samples: sample k sits at position k, and at s = 0 the
// value is the sample itself.
//
// Near the record's ends the kernel would reach past them, and no
// extension of the record (held, mirrored) comes close to a sine there
// (10 % of the amplitude at 0.2 of the sample rate); the not-a-knot spline,
// whose end conditions extrapolate the record's own curvature, errs by 5 %
// there. A caller uses the spline where reaches() is false.
#include <array>
#include <cstddef>
#include <span>

namespace hystbench {

class BandLimitedKernel {
 public:
  static constexpr int kHalfWidth = 12;
  static constexpr int kTaps = 2 * kHalfWidth;

  // Weight t multiplies sample k − kHalfWidth + 1 + t for the value at
  // position k + s, 0 <= s <= 1 (the same for every interval, so a caller
  // evaluating many intervals at the same fractions computes them once).
  using Weights = std::array<double, kTaps>;
  static Weights weights(double s);

  // Whether the kernel of the interval from sample k stays inside a record
  // of n samples.
  static bool reaches(std::ptrdiff_t k, std::size_t n) {
    return k >= kHalfWidth - 1 && k + kHalfWidth < std::ptrdiff_t(n);
  }

  // Value at position k + s (reaches(k, w.size()) true) with the
  // precomputed weights of s, for any element type with double arithmetic:
  // a vector of several records' samples (a block of candidates) gets in
  // each lane exactly what a double gets.
  template <class V>
  static V value(std::span<const V> w, std::ptrdiff_t k, const Weights& c) {
    const V* first = w.data() + (k - kHalfWidth + 1);
    V sum = c[0] * first[0];
    for (int t = 1; t < kTaps; ++t) sum = sum + c[std::size_t(t)] * first[t];
    return sum;
  }
};

}  // namespace hystbench
