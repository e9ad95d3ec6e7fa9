#include "framework/tracking/uncertainty_weight.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "framework/core/error.hpp"
#include "framework/io/segment_runs.hpp"
#include "framework/io/measurement.hpp"
#include "framework/model/spectrum.hpp"
#include "framework/robust/linear_system.hpp"

namespace hystbench {
namespace {

constexpr double kWarmUp = 0.2;  // share of a segment left out while the loop settles

// Amplitude phasor of x at `hz` over the whole periods of [begin, end).
std::complex<double> phasor(const Eigen::VectorXd& x, Eigen::Index begin, Eigen::Index end, double hz,
                            double dt) {
  const double period = 1.0 / (hz * dt);
  const Eigen::Index n = Eigen::Index(std::floor(double(end - begin) / period) * period);
  std::complex<double> sum = 0.0;
  for (Eigen::Index k = 0; k < n; ++k)
    sum += x[begin + k] * std::polar(1.0, -2.0 * std::numbers::pi * hz * dt * double(k));
  return n > 0 ? 2.0 * sum / double(n) : 0.0;
}

// The strongest frequency of x on [begin, end): Welch's peak, refined on a
// grid one bin either side.
double dominant_hz(const Eigen::VectorXd& x, Eigen::Index begin, Eigen::Index end, double dt) {
  const Eigen::VectorXd part = x.segment(begin, end - begin);
  const Spectrum s = welch_spectrum(part, dt, int(std::min<Eigen::Index>(part.size(), 8192)));
  if (s.power.size() < 3) return 0.0;
  const auto peak = std::max_element(s.power.begin() + 1, s.power.end()) - s.power.begin();
  const double bin = s.frequency[1];
  double best = s.frequency[peak], best_amplitude = 0.0;
  for (int i = -20; i <= 20; ++i) {
    const double hz = s.frequency[peak] + bin * i / 20.0;
    if (hz <= 0.0 || hz * dt * double(end - begin) < 2.0) continue;  // two periods at least
    const double a = std::abs(phasor(x, begin, end, hz, dt));
    if (a > best_amplitude) best = hz, best_amplitude = a;
  }
  return best_amplitude > 0.0 ? best : 0.0;
}

// The model is driven by the record from rest. An SVR front answers for
// the next sample: its output is compared one sample on.
std::vector<UncertaintyPoint> record_points(const IdentifiedSource& model, const std::filesystem::path& path,
                                            const std::string& where) {
  const Measurement m = read_measurement(path);
  auto stream = model.make(m.sample_time);
  const Eigen::Index lead = model.sample_time > 0.0 ? 1 : 0;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(m.size()), e = Eigen::VectorXd::Zero(m.size());
  for (Eigen::Index k = 0; k + lead < m.size(); ++k) {
    w[k + lead] = stream->step_front(m.u[k]);
    e[k + lead] = m.y[k + lead] - stream->step_back(w[k + lead]);
  }
  if (!e.allFinite()) throw InputError(where + ": the identified model diverges on " + path.string());
  std::vector<UncertaintyPoint> points;
  for (const SegmentRun& run : segment_runs(m.segment, m.size())) {
    const Eigen::Index begin = run.begin + Eigen::Index(kWarmUp * double(run.size()));
    const double hz = dominant_hz(w, begin, run.end, m.sample_time);
    if (hz <= 0.0) continue;
    const double a = std::abs(phasor(w, begin, run.end, hz, m.sample_time));
    if (a <= 0.0) continue;
    points.push_back({path.filename().string(), run.label, hz,
                      std::abs(phasor(e, begin, run.end, hz, m.sample_time)) / a});
  }
  return points;
}

UncertaintyWeight from_transfer(std::string source, std::vector<double> num, std::vector<double> den) {
  UncertaintyWeight w;
  w.source = std::move(source);
  w.weight = robust::transfer_function(num, den);
  w.num = std::move(num);
  w.den = std::move(den);
  return w;
}

}  // namespace

UncertaintyWeight seed_uncertainty_weight() {
  const double k = -0.07652;
  // k (s² + 49.662 s + 157.80) / (s² + 86.456 s + 616.77), expanded from the factors.
  return from_transfer("seed 002, eq. 21", {k, k * (3.412 + 46.25), k * 3.412 * 46.25},
                       {1.0, 78.61 + 7.846, 78.61 * 7.846});
}

UncertaintyWeight given_uncertainty_weight(const std::vector<double>& num, const std::vector<double>& den,
                                           const std::string& where) {
  UncertaintyWeight w;
  try {
    w = from_transfer("given in the experiment", num, den);
  } catch (const InputError& e) {
    throw InputError(where + ": the weight num/den: " + e.what() + "; a weight needs as many poles as zeros or more");
  }
  if (!robust::is_stable(w.weight, robust::TimeDomain::Continuous))
    throw InputError(where + ": the weight num/den has a pole in the right half plane or on the axis; "
                             "give a stable weight (only its magnitude matters)");
  return w;
}

UncertaintyWeight residual_uncertainty_weight(const IdentifiedSource& model,
                                              const std::vector<std::filesystem::path>& records,
                                              double margin, double rise, const std::string& where) {
  if (!(margin >= 1.0)) throw InputError(where + ".margin: must be at least 1 (the weight bounds the points)");
  if (!(rise >= 1.0)) throw InputError(where + ".rise: must be at least 1 (the weight may not fall)");
  std::vector<UncertaintyPoint> points;
  for (const auto& path : records) {
    auto more = record_points(model, path, where);
    points.insert(points.end(), more.begin(), more.end());
  }
  if (points.empty())
    throw InputError(where + ": no segment of the records has a dominant frequency to measure the residual at");
  double largest = 0.0, top_hz = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.bound), top_hz = std::max(top_hz, p.hz);
  const double k0 = margin * largest, kinf = rise * k0, wc = 2.0 * std::numbers::pi * top_hz;
  UncertaintyWeight w = from_transfer("identification residual", {kinf, wc * k0}, {1.0, wc});
  w.points = std::move(points);
  w.margin = margin, w.rise = rise;
  return w;
}

}  // namespace hystbench
