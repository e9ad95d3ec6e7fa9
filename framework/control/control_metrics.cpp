#include "framework/control/control_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/control/control_loop.hpp"

namespace hystbench {

long MetricWindows::steady_samples() const { return std::lround(steady_s * sample_rate_hz); }

double steady_rms(const std::vector<double>& x, const MetricWindows& w) {
  const std::size_t n = std::min(x.size(), std::size_t(w.steady_samples()));
  double sum = 0.0;
  for (std::size_t i = x.size() - n; i < x.size(); ++i) sum += x[i] * x[i];
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

namespace {

double convergence_time(const std::vector<double>& e, double threshold, const MetricWindows& w) {
  const long window = std::lround(w.sample_rate_hz);
  const auto rms = moving_rms(e, window);
  // The last sample at which the moving RMS is still at or above the threshold.
  std::size_t last_above = 0;
  bool any_above = false;
  for (std::size_t n = 0; n < rms.size(); ++n)
    if (rms[n] >= threshold) last_above = n, any_above = true;
  if (!any_above) return 0.0;
  if (last_above + 1 >= rms.size()) return std::numeric_limits<double>::quiet_NaN();
  return double(last_above + 1) / w.sample_rate_hz;
}

}  // namespace

SuppressionMetrics suppression_metrics(const std::vector<double>& on, const std::vector<double>& off,
                           const MetricWindows& w) {
  SuppressionMetrics m;
  double sum_sq = 0.0, sum_abs = 0.0;
  for (double e : on) sum_sq += e * e, sum_abs += std::abs(e);
  m.rmse = std::sqrt(sum_sq / double(on.size()));
  m.mae = sum_abs / double(on.size());
  const double a_off = steady_rms(off, w), a_on = steady_rms(on, w);
  m.efficiency_percent = 100.0 * (a_off - a_on) / a_off;
  m.attenuation_db = 20.0 * std::log10(a_off / a_on);
  m.convergence_s = convergence_time(on, 0.1 * a_off, w);
  return m;
}

}  // namespace hystbench
