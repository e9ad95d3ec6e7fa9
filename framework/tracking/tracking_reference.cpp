#include "framework/tracking/tracking_reference.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

constexpr double kResolutionHz = 1e-3;

double shape(const std::vector<double>& hz, double t) {
  double s = 0.0;
  for (double f : hz) s -= std::cos(2.0 * std::numbers::pi * f * t);
  return s;
}

std::string frequencies_of(const std::vector<double>& hz) {
  std::string out;
  for (double f : hz) out += (out.empty() ? "" : "/") + format_number("%g", f);
  return out;
}

}  // namespace

double TrackingReference::value(double t) const { return offset + amplitude * shape(hz, t) / peak; }

TrackingReference make_reference(const std::vector<double>& hz, double amplitude, double offset,
                                 const std::string& where) {
  if (hz.empty()) throw InputError(where + ": give at least one frequency");
  if (!(amplitude > 0.0) || !std::isfinite(amplitude)) throw InputError(where + ": the amplitude must be positive");
  if (!std::isfinite(offset)) throw InputError(where + ": the offset must be a finite number");
  long long common = 0;
  for (double f : hz) {
    const double units = f / kResolutionHz;
    if (!(f > 0.0) || std::abs(units - std::round(units)) > 1e-6 * units || units > 1e12)
      throw InputError(where + ": frequencies must be positive multiples of 1 mHz (got " + format_number("%g", f) +
                       ")");
    common = std::gcd(common, static_cast<long long>(std::llround(units)));
  }
  TrackingReference r{frequencies_of(hz) + " Hz", frequencies_of(hz), hz, amplitude, offset,
                      double(common) * kResolutionHz, 1.0, 1.0};
  // s(0) = −n is the lowest point; the highest is searched over a period.
  r.peak = double(hz.size());
  r.top = -r.peak;
  const int n = 20000;
  for (int i = 0; i < n; ++i) r.top = std::max(r.top, shape(hz, double(i) / (n * r.fundamental_hz)));
  r.peak = std::max(r.peak, r.top);
  return r;
}

WindowSamples window_samples(const TrackingReference& r, const ScoreWindow& w, double sample_time) {
  const double period_s = 1.0 / r.fundamental_hz;
  WindowSamples s;
  s.period = period_s / sample_time;
  if (s.period < 4.0)
    throw InputError("reference " + r.label + ": its period is shorter than 4 samples at " +
                     format_number("%g", 1.0 / sample_time) + " Hz");
  const double settle = std::max(period_s, w.settle_s);
  s.begin = Eigen::Index(std::llround(std::ceil(settle / period_s - 1e-9) * s.period));
  s.periods = std::max(1, int(std::ceil(w.length_s / period_s - 1e-9)));
  return s;
}

TrackingScore score_tracking(const Eigen::VectorXd& reference, const Eigen::VectorXd& output,
                             const WindowSamples& w, double offset) {
  TrackingScore s;
  double abs_error = 0.0, abs_output = 0.0, squared = 0.0;
  for (int p = 0; p < w.periods; ++p) {
    double period_squared = 0.0;
    const Eigen::Index from = w.boundary(p), to = w.boundary(p + 1);
    for (Eigen::Index k = from; k < to; ++k) {
      const double e = output[k] - reference[k];
      period_squared += e * e;
      abs_error += std::abs(e);
      abs_output += std::abs(output[k] - offset);
      s.max_error = std::max(s.max_error, std::abs(e));
    }
    squared += period_squared;
    s.armse += std::sqrt(period_squared / double(to - from)) / w.periods;
  }
  s.rmse = std::sqrt(squared / double(w.end() - w.begin));
  s.re = abs_output > 0.0 ? abs_error / abs_output : 0.0;
  return s;
}

}  // namespace hystbench
