#pragma once
// What a control run achieved (docs/control.md#metrics), against the
// uncontrolled run with the same noise:
//
//   rmse, mae            of the error over the whole run (the target is 0)
//   efficiency_percent   (A_off - A_on) / A_off * 100, A = RMS over the
//                        steady window (the last `steady_s`); RECONSTRUCTION
//                        of seed 000's eq. (31)
//   attenuation_db       20 log10(A_off / A_on)
//   convergence_s        the time after which the 1 s moving RMS stays below
//                        10 % of A_off (-20 dB); NaN when it never does
//
// Each is computed on the measured error and on the true (noise-free) one.
#include <vector>

namespace hystbench {

struct SuppressionMetrics {
  double rmse = 0.0;
  double mae = 0.0;
  double efficiency_percent = 0.0;
  double attenuation_db = 0.0;
  double convergence_s = 0.0;
};

// The metrics by name, in the order of control.json and the CSV tables.
struct MetricField {
  const char* name;
  double SuppressionMetrics::*field;
};
inline constexpr MetricField kSuppressionMetrics[] = {
    {"rmse", &SuppressionMetrics::rmse},
    {"mae", &SuppressionMetrics::mae},
    {"efficiency_percent", &SuppressionMetrics::efficiency_percent},
    {"attenuation_db", &SuppressionMetrics::attenuation_db},
    {"convergence_s", &SuppressionMetrics::convergence_s},
};

struct MetricWindows {
  double sample_rate_hz = 1000.0;
  double steady_s = 10.0;
  long steady_samples() const;
};

// RMS of the last `steady_s` of a run.
double steady_rms(const std::vector<double>& x, const MetricWindows& w);

// `off` is the uncontrolled error of the same length and noise.
SuppressionMetrics suppression_metrics(const std::vector<double>& on, const std::vector<double>& off,
                           const MetricWindows& w);

}  // namespace hystbench
