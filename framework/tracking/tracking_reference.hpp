#pragma once
// The references of seed 002's Table 2 and how a tracking run is scored
// (docs/tracking.md#references-and-scores).
//
// A reference is offset + amplitude · s(t)/max|s| with s(t) = −Σ cos(2π f_i t):
// a sine, or the equal-amplitude sum of several, normalised to the
// amplitude and starting at its lowest point (offset − amplitude), so a
// unipolar actuator starts at rest. The seed does not say how it built its
// compound signals; equal components and peak normalisation are our choice.
//
// Scores are over whole periods of the fundamental T0 = 1/gcd(f_i), after
// max(T0, settle) of settling, on ⌈window/T0⌉ periods:
//   ARMSE = the mean over those periods of each period's RMS error;
//   RE    = Σ|e| / Σ|y − offset|, seed 002's eq. 18 about the reference's
//           centre (the seed's records are centred on zero).
#include "framework/core/eigen.hpp"
#include <cmath>
#include <string>
#include <vector>

namespace hystbench {

struct TrackingReference {
  std::string label;        // "10 Hz", "10/20/40 Hz", "10 Hz amplitude 15"
  std::string frequencies;  // "10", "10/20/40"
  std::vector<double> hz;
  double amplitude = 0.0, offset = 0.0;
  double fundamental_hz = 0.0;
  double peak = 1.0;  // max |s| over a fundamental period (at t = 0: s(0) = −n)
  double top = 1.0;   // max s

  double value(double t) const;
  double lowest() const { return offset - amplitude; }
  double highest() const { return offset + amplitude * top / peak; }
};

// Throws InputError naming `where` for a non-positive or incommensurate
// frequency (no common period within 1 mHz) or a non-positive amplitude.
TrackingReference make_reference(const std::vector<double>& hz, double amplitude, double offset,
                                 const std::string& where);

struct ScoreWindow {
  double settle_s = 0.2;  // at least one fundamental period
  double length_s = 0.1;  // whole periods covering at least this
};

// Periods need not be whole numbers of samples (30 Hz at 10 kHz): period p
// covers samples [boundary(p), boundary(p + 1)).
struct WindowSamples {
  Eigen::Index begin = 0;
  double period = 0.0;  // samples
  int periods = 0;
  Eigen::Index boundary(int p) const { return begin + Eigen::Index(std::llround(p * period)); }
  Eigen::Index end() const { return boundary(periods); }
};

// Throws InputError when a period is shorter than four samples.
WindowSamples window_samples(const TrackingReference& r, const ScoreWindow& w, double sample_time);

struct TrackingScore {
  double armse = 0.0, re = 0.0, rmse = 0.0, max_error = 0.0;
};

TrackingScore score_tracking(const Eigen::VectorXd& reference, const Eigen::VectorXd& output,
                             const WindowSamples& window, double offset);

}  // namespace hystbench
