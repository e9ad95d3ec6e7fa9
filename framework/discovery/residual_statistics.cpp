#include "framework/discovery/residual_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/discovery/breakdowns.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/segment_runs.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

double std_dev(const Eigen::VectorXd& v) {
  if (v.size() < 2) return kNaN;
  return std::sqrt((v.array() - v.mean()).square().sum() / double(v.size() - 1));
}

Eigen::VectorXd differences(const Eigen::VectorXd& v) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(v.size());
  for (Eigen::Index k = 1; k < v.size(); ++k) d[k] = v[k] - v[k - 1];
  if (v.size() > 1) d[0] = d[1];
  return d;
}

// Central differences divided by 2Ts (one-sided at the ends).
Eigen::VectorXd derivative(const Eigen::VectorXd& v, double ts) {
  const Eigen::Index n = v.size();
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  if (n < 2) return d;
  for (Eigen::Index k = 1; k + 1 < n; ++k) d[k] = (v[k + 1] - v[k - 1]) / (2 * ts);
  d[0] = (v[1] - v[0]) / ts;
  d[n - 1] = (v[n - 1] - v[n - 2]) / ts;
  return d;
}

struct Saturation {
  double ratio = kNaN, sse_share = kNaN, sample_share = kNaN;
};

Saturation saturation(const SignatureInput& in) {
  std::vector<double> edges;
  const auto bin = amplitude_bins(in.u, edges);
  double top_sse = 0, total = in.e.squaredNorm();
  long top_n = 0;
  for (std::size_t i = 0; i < bin.size(); ++i)
    if (bin[i] == kAmplitudeBins - 1)
      top_sse += in.e[Eigen::Index(i)] * in.e[Eigen::Index(i)], ++top_n;
  Saturation s;
  if (bin.empty() || !(edges.back() > 0)) return s;
  s.sample_share = double(top_n) / double(bin.size());
  if (total > 0) s.sse_share = top_sse / total, s.ratio = s.sse_share / s.sample_share;
  return s;
}

// Lowest dominant frequency over the segment runs; 1 / duration when none
// oscillates.
double lowest_frequency(const SignatureInput& in) {
  double low = kNaN;
  for (const auto& r : segment_runs(in.segment, in.u.size())) {
    const double f = crossing_frequency(in.u, r.begin, r.end, in.sample_time);
    if (std::isfinite(f) && !(f >= low)) low = f;
  }
  return std::isfinite(low) ? low : 1.0 / (double(in.u.size()) * in.sample_time);
}

Eigen::VectorXd first_order_lag(const Eigen::VectorXd& u, double tau, double ts) {
  Eigen::VectorXd out(u.size());
  const double a = std::exp(-ts / tau);
  double state = u.size() ? u[0] : 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) out[k] = state = a * state + (1 - a) * u[k];
  return out;
}

// Variance of the centred moving mean over `w` samples, as a share of var(e).
double low_frequency_share(const Eigen::VectorXd& e, Eigen::Index w) {
  const Eigen::Index n = e.size();
  if (w < 2 || 2 * w > n) return kNaN;
  const Eigen::VectorXd ec = (e.array() - e.mean()).matrix();
  const double total = ec.squaredNorm() / double(n);
  if (!(total > 0)) return kNaN;
  double window = ec.head(w).sum(), power = 0;
  for (Eigen::Index k = 0;; ++k) {
    power += (window / double(w)) * (window / double(w));
    if (k + w >= n) break;
    window += ec[k + w] - ec[k];
  }
  return power / double(n - w + 1) / total;
}

struct FrequencyTrend {
  double correlation = kNaN, slope = kNaN;
};

FrequencyTrend frequency_trend(const SignatureInput& in) {
  std::vector<double> f, rmse;
  for (const auto& label : distinct_labels(in.segment)) {
    double sse = 0, crossings_f = 0;
    long n = 0, runs = 0;
    for (const auto& r : segment_runs(in.segment, in.u.size())) {
      if (r.label != label) continue;
      sse += in.e.segment(r.begin, r.size()).squaredNorm();
      n += long(r.size());
      const double fr = crossing_frequency(in.u, r.begin, r.end, in.sample_time);
      if (std::isfinite(fr)) crossings_f += fr, ++runs;
    }
    if (runs > 0 && n > 0)
      f.push_back(crossings_f / double(runs)), rmse.push_back(std::sqrt(sse / double(n)));
  }
  FrequencyTrend trend;
  std::vector<double> sorted = f;
  std::sort(sorted.begin(), sorted.end());
  // Frequencies within 1 % count as the same.
  const auto distinct =
      std::unique(sorted.begin(), sorted.end(),
                  [](double a, double b) { return std::abs(a - b) <= 0.01 * b; }) -
      sorted.begin();
  if (distinct < 3) return trend;
  const Eigen::Map<Eigen::VectorXd> fv(f.data(), Eigen::Index(f.size()));
  const Eigen::Map<Eigen::VectorXd> rv(rmse.data(), Eigen::Index(rmse.size()));
  trend.correlation = correlation(fv.array().log10().matrix(), rv);
  const Eigen::ArrayXd fc = fv.array() - fv.mean();
  trend.slope = (fc * (rv.array() - rv.mean())).sum() / fc.square().sum();
  return trend;
}

double ccf_max_over_bound(const Correlation& ccf) {
  double best = kNaN;
  for (std::size_t i = 0; i < ccf.lags.size(); ++i)
    if (ccf.lags[i] > 0 && std::isfinite(ccf.values[i]) && !(std::abs(ccf.values[i]) <= best))
      best = std::abs(ccf.values[i]);
  return best / ccf.bound;
}

double ccf_at(const Correlation& ccf, int lag) {
  for (std::size_t i = 0; i < ccf.lags.size(); ++i)
    if (ccf.lags[i] == lag) return ccf.values[i];
  return kNaN;
}

}  // namespace

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() < 2 || a.size() != b.size()) return kNaN;
  const Eigen::ArrayXd ac = a.array() - a.mean(), bc = b.array() - b.mean();
  const double scale = std::sqrt(ac.square().sum() * bc.square().sum());
  return scale > 0 ? (ac * bc).sum() / scale : kNaN;
}

double crossing_frequency(const Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index end,
                          double sample_time) {
  if (end - begin < 3 || !(sample_time > 0)) return kNaN;
  const double mean = u.segment(begin, end - begin).mean();
  long crossings = 0;
  for (Eigen::Index k = begin + 1; k < end; ++k)
    if ((u[k - 1] - mean < 0) != (u[k] - mean < 0)) ++crossings;
  if (crossings < 2) return kNaN;
  return double(crossings) / (2.0 * double(end - begin) * sample_time);
}

nlohmann::json residual_signatures(const SignatureInput& in) {
  const Eigen::VectorXd& e = in.e;
  const Saturation sat = saturation(in);
  const double f_low = lowest_frequency(in);
  const double period = 1.0 / f_low;
  const Eigen::VectorXd u_slow = first_order_lag(in.u, period, in.sample_time);
  const FrequencyTrend trend = frequency_trend(in);
  const Eigen::VectorXd u2 = in.u.array().square().matrix();
  Eigen::VectorXd direction(in.u.size());
  const auto branch = branches(in.u);
  for (std::size_t i = 0; i < branch.size(); ++i) direction[Eigen::Index(i)] = branch[i];
  const Eigen::VectorXd rate = differences(in.u).cwiseAbs();
  const Eigen::VectorXd slope = -derivative(in.y_model, in.sample_time);
  const double slope_energy = slope.squaredNorm();
  const int lag = peak_lag(in.ccf);
  return {
      {"offset", finite_or_null(e.size() ? e.mean() / std_dev(e) : kNaN)},
      {"drift", finite_or_null(correlation(e, in.t))},
      {"asymmetry", finite_or_null(correlation(e, u2))},
      {"backlash", finite_or_null(correlation(e, direction))},
      {"saturation", finite_or_null(sat.ratio)},
      {"saturation_sse_share", finite_or_null(sat.sse_share)},
      {"saturation_sample_share", finite_or_null(sat.sample_share)},
      {"creep", finite_or_null(correlation(e, u_slow))},
      {"creep_low_frequency_share",
       finite_or_null(low_frequency_share(e, Eigen::Index(std::llround(period / in.sample_time))))},
      {"lowest_excitation_hz", finite_or_null(f_low)},
      {"dynamics_rate_correlation", finite_or_null(correlation(e.cwiseAbs(), rate))},
      {"dynamics_frequency_correlation", finite_or_null(trend.correlation)},
      {"dynamics_rmse_per_hz", finite_or_null(trend.slope)},
      {"dynamics_ccf_max_over_bound", finite_or_null(ccf_max_over_bound(in.ccf))},
      {"delay_lag", lag},
      {"delay_ccf", finite_or_null(ccf_at(in.ccf, lag))},
      {"delay_correlation", finite_or_null(correlation(e, slope))},
      {"delay_seconds", finite_or_null(slope_energy > 0 ? e.dot(slope) / slope_energy : kNaN)},
  };
}

}  // namespace hystbench
