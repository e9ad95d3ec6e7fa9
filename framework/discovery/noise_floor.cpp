#include "framework/discovery/noise_floor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/io/segment_runs.hpp"
#include "framework/model/spectrum.hpp"
#include "framework/stats/descriptive.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr Eigen::Index kMinPeriod = 4;
// Fewer sample pairs than this say little about σ.
constexpr long kMinPairs = 32;
// Median |x| / 1.4826 is σ for Gaussian x.
constexpr double kMadToSigma = 1.4826;

struct PairSum {
  double squares = 0;
  long pairs = 0;
  Eigen::Index period = 0;
  void add(const Eigen::VectorXd& y, Eigen::Index from, Eigen::Index to, Eigen::Index shift) {
    for (Eigen::Index k = from; k < to; ++k) {
      const double d = y[k] - y[k + shift];
      squares += d * d;
    }
    pairs += long(std::max<Eigen::Index>(0, to - from));
  }
  bool enough() const { return pairs >= kMinPairs; }
  double sigma() const { return std::sqrt(squares / double(pairs) / 2.0); }
};

double range(const Eigen::VectorXd& v, Eigen::Index begin, Eigen::Index end) {
  if (end <= begin) return 0.0;
  const auto s = v.segment(begin, end - begin);
  return s.maxCoeff() - s.minCoeff();
}

// Smallest P >= kMinPeriod with u[k + P] == u[k] (to `tol`) for every k of
// [begin, end − P) and at least two periods; 0 when there is none.
Eigen::Index exact_period(const Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index end) {
  const double span = range(u, begin, end);
  if (!(span > 0) || !std::isfinite(span)) return 0;
  const double tol = 1e-6 * span;
  for (Eigen::Index p = kMinPeriod; 2 * p <= end - begin; ++p) {
    Eigen::Index k = begin;
    while (k + p < end && std::abs(u[k + p] - u[k]) <= tol) ++k;
    if (k + p == end) return p;
  }
  return 0;
}

// Differences one period apart over [begin, end), from the second half of
// the periods on: the first periods still carry the start-up transient
// (the initial loading curve, a decaying resonance). With m periods the
// pairs (p, p + 1) for p >= floor(m / 2) are used, so two periods give none.
void add_periodic(PairSum& sum, const Eigen::VectorXd& y, Eigen::Index begin, Eigen::Index end,
                  Eigen::Index p) {
  const Eigen::Index periods = (end - begin) / p;
  const Eigen::Index from = begin + (periods / 2) * p, to = begin + (periods - 1) * p;
  if (to <= from) return;
  sum.add(y, from, to, p);
  sum.period = sum.period ? sum.period : p;
}

PairSum periodic_within_runs(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                             const std::vector<SegmentRun>& runs) {
  PairSum sum;
  for (const auto& r : runs)
    if (const Eigen::Index p = exact_period(u, r.begin, r.end))
      add_periodic(sum, y, r.begin, r.end, p);
  return sum;
}

bool same_input(const Eigen::VectorXd& u, const SegmentRun& a, const SegmentRun& b) {
  const auto ua = u.segment(a.begin, a.size()), ub = u.segment(b.begin, b.size());
  const double spread = (ua.array() - ua.mean()).matrix().norm();
  return spread > 0 && (ua - ub).norm() <= 0.05 * spread;
}

// A label that comes back with runs of the same length and input: its
// occurrences are periods, paired like add_periodic pairs periods (the
// second half of the occurrences, each with the next).
PairSum repeated_labels(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                        const std::vector<SegmentRun>& runs) {
  PairSum sum;
  std::vector<std::string> labels;
  for (const auto& r : runs) labels.push_back(r.label);
  for (const auto& label : distinct_labels(labels)) {
    std::vector<const SegmentRun*> occurrences;
    for (const auto& r : runs)
      if (r.label == label) occurrences.push_back(&r);
    const std::size_t m = occurrences.size();
    for (std::size_t p = m / 2; p + 1 < m; ++p) {
      const SegmentRun& a = *occurrences[p];
      const SegmentRun& b = *occurrences[p + 1];
      if (a.size() == b.size() && same_input(u, a, b))
        sum.add(y, a.begin, a.end, b.begin - a.begin);
    }
  }
  return sum;
}

// Welch segments: long enough to resolve the band edge, short enough to
// average at least eight segments.
constexpr int kLongestSpectralSegment = 1024, kShortestSpectralSegment = 64;
constexpr double kExcitedShare = 1e-3, kQuietShare = 1e-4;
constexpr std::size_t kFewestQuietBins = 16;

int spectral_segment(Eigen::Index n) {
  int length = kLongestSpectralSegment;
  while (length > kShortestSpectralSegment && 8 * Eigen::Index(length) > n) length /= 2;
  return 8 * Eigen::Index(length) <= n ? length : 0;
}

// σ from the output's power where the input has none, for an input that
// reaches above fs/6; method "none" when that does not apply.
NoiseFloor spectral_noise_floor(const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  NoiseFloor f{kNaN, "none", 0, 0, 0};
  const int length = spectral_segment(u.size());
  if (length == 0) return f;
  const Spectrum su = welch_spectrum(u, 1.0, length), sy = welch_spectrum(y, 1.0, length);
  const double peak = *std::max_element(su.power.begin(), su.power.end());
  const std::size_t bins = su.power.size();
  bool reaches_sixth = false;
  std::vector<double> quiet;
  for (std::size_t b = 2; b < bins; ++b) {
    reaches_sixth |= su.frequency[b] >= 1.0 / 6.0 && su.power[b] >= kExcitedShare * peak;
    if (su.power[b] < kQuietShare * peak) {
      if (quiet.empty()) f.quiet_from = su.frequency[b];
      quiet.push_back(sy.power[b]);
    }
  }
  if (!(peak > 0) || !reaches_sixth || quiet.size() < std::max(kFewestQuietBins, bins / 8))
    return f;
  const double window_energy = 3.0 * length / 8.0;  // Σ w² of the periodic Hann window
  f.method = "spectral";
  f.sigma = std::sqrt(stats::median(quiet) / window_energy);
  f.pairs = long(quiet.size());
  return f;
}

double binomial(int n, int k) {
  double c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

}  // namespace

NoiseFloor difference_noise_floor(const Eigen::VectorXd& y) {
  NoiseFloor f{kNaN, "none", 0, 0, 0};
  constexpr int kMaxOrder = 6;
  static_assert(kNoiseFloorFewestSamples == kMaxOrder + 2);
  if (y.size() < kNoiseFloorFewestSamples) return f;
  f.method = "difference_mad";
  f.sigma = std::numeric_limits<double>::infinity();
  for (int m = 2; m <= kMaxOrder; ++m) {
    std::vector<double> d(std::size_t(y.size() - m));
    for (Eigen::Index k = 0; k + m < y.size(); ++k) {
      double s = 0;
      for (int j = 0; j <= m; ++j) s += (j % 2 ? -1.0 : 1.0) * binomial(m, j) * y[k + j];
      d[std::size_t(k)] = std::abs(s);
    }
    const double sigma = kMadToSigma * stats::median(d) / std::sqrt(binomial(2 * m, m));
    if (sigma < f.sigma) f.sigma = sigma, f.order = m;
  }
  return f;
}

NoiseFloor estimate_noise_floor(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                                const std::vector<std::string>& segment) {
  const auto runs = segment_runs(segment, y.size());
  PairSum sum = periodic_within_runs(u, y, runs);
  if (!sum.enough() && !segment.empty()) {
    sum = PairSum{};
    if (const Eigen::Index p = exact_period(u, 0, u.size())) add_periodic(sum, y, 0, u.size(), p);
  }
  if (!sum.enough()) sum = repeated_labels(u, y, runs);
  if (sum.enough()) return {sum.sigma(), "periodic", sum.pairs, sum.period, 0};
  if (const NoiseFloor f = spectral_noise_floor(u, y); f.method == "spectral") return f;
  return difference_noise_floor(y);
}

}  // namespace hystbench
