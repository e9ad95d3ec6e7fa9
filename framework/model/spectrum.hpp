#pragma once
// Power spectrum of a signal by Welch's method (Welch, IEEE Trans. Audio
// Electroacoust. 15 (1967)): Hann-windowed segments of `length` samples,
// half overlapping, with their mean removed; the periodograms averaged.
// Averaging K segments gives every bin a χ²(2K)/2K spread, so a white
// signal's spectrum is flat to within a few 1/√K and narrow peaks stand out.
#include "framework/core/eigen.hpp"
#include <vector>

namespace hystbench {

struct Spectrum {
  std::vector<double> frequency;  // Hz, bins 0 .. length/2
  std::vector<double> power;      // per bin, in units of x² (relative levels are what counts)
};

// `length` is shortened to the record when the record is shorter (at least 8
// samples; otherwise the spectrum is empty).
Spectrum welch_spectrum(const Eigen::VectorXd& x, double sample_time, int length = 256);

}  // namespace hystbench
