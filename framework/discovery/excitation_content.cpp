#include "framework/discovery/excitation_content.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "framework/core/text.hpp"
#include "framework/io/segment_runs.hpp"

namespace hystbench {
namespace {

constexpr double kToneShare = 0.8;  // of the power within ±3 bins of the peak
constexpr double kBandShare = 0.9;
constexpr double kLineShare = 0.05;  // a spectral line that counts as a frequency of the record

// Rests of one run: stretches within kRestTolerance of the record's range
// (`range`) of their first sample, at least kShortestRestSeconds and 20
// samples long (any length when the whole record is constant). A rest
// follows a change unless it starts the record or continues, at the same
// level, a rest that ended where it begins (`before`, of the earlier runs).
std::vector<RestPart> rests_of(const Eigen::VectorXd& u, const SegmentRun& run, double ts, double range,
                               const std::vector<RestPart>& before) {
  const Eigen::VectorXd x = u.segment(run.begin, run.size());
  const double tolerance = kRestTolerance * range;
  const auto shortest = Eigen::Index(std::max(20.0, std::ceil(kShortestRestSeconds / ts)));
  std::vector<RestPart> out;
  Eigen::Index start = 0;
  while (start < x.size()) {
    Eigen::Index k = start + 1;
    while (k < x.size() && std::abs(x[k] - x[start]) <= tolerance) ++k;
    if (k - start >= shortest || range == 0) {
      RestPart r{run.begin + start, run.begin + k, x.segment(start, k - start).mean(), false};
      const RestPart* previous = !out.empty() ? &out.back() : !before.empty() ? &before.back() : nullptr;
      const bool continues = previous && previous->end == r.begin && std::abs(r.level - previous->level) <= tolerance;
      r.after_change = r.begin > 0 && !continues;
      out.push_back(r);
    }
    start = k;
  }
  return out;
}

// Half peak-to-peak over windows of one period: the smallest and largest
// (10th and 90th percentiles when there are ten windows or more, so a
// start-up or a glitch does not decide).
std::pair<double, double> amplitude_range(const Eigen::VectorXd& x, Eigen::Index window) {
  window = std::clamp<Eigen::Index>(window, 2, x.size());
  std::vector<double> a;
  for (Eigen::Index b = 0; b + window <= x.size(); b += window) {
    const auto w = x.segment(b, window);
    a.push_back(0.5 * (w.maxCoeff() - w.minCoeff()));
  }
  if (a.empty()) return {0.0, 0.0};
  std::sort(a.begin(), a.end());
  if (a.size() < 10) return {a.front(), a.back()};  // too few windows for percentiles
  const auto at = [&](double q) { return a[std::size_t(std::floor(q * double(a.size() - 1)))]; };
  return {at(0.1), at(0.9)};
}

// Power per bin of the whole part (mean removed, zero-padded to a power of
// two): one periodogram, so a part made of several tones one after another
// has all of them in it. A Tukey window (cosine tapers over 5 % at each
// end) keeps the leakage of the ends small without suppressing a tone that
// comes last, as a Hann window over the whole part would.
double tukey(Eigen::Index k, Eigen::Index n) {
  const double taper = 0.05 * double(n), d = double(std::min(k, n - 1 - k));
  return d >= taper ? 1.0 : 0.5 - 0.5 * std::cos(M_PI * d / taper);
}


std::vector<double> periodogram(const Eigen::VectorXd& x) {
  std::size_t length = 8;
  while (length < std::size_t(x.size())) length *= 2;
  std::vector<double> padded(length, 0.0);
  const double mean = x.mean();
  for (Eigen::Index k = 0; k < x.size(); ++k)
    padded[std::size_t(k)] = (x[k] - mean) * tukey(k, x.size());
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> transform;
  fft.fwd(transform, padded);
  std::vector<double> power(length / 2 + 1);
  for (std::size_t b = 0; b < power.size(); ++b) power[b] = std::norm(transform[b]);
  return power;
}

// Spectral lines: local maxima whose ±`reach` bins hold at least
// kLineShare of the power, as {frequency, share}, strongest first.
std::vector<std::pair<double, double>> spectral_lines(const std::vector<double>& power, double total,
                                                      std::size_t reach, double df) {
  std::vector<std::pair<double, double>> lines;
  for (std::size_t b = 1; b < power.size(); ++b) {
    const std::size_t lo = b > reach ? b - reach : 1, hi = std::min(b + reach, power.size() - 1);
    double near = 0;
    bool is_max = true;
    for (std::size_t c = lo; c <= hi; ++c) {
      near += power[c];
      is_max = is_max && (power[c] < power[b] || (power[c] == power[b] && c >= b));
    }
    if (is_max && near >= kLineShare * total) lines.push_back({double(b) * df, near / total});
  }
  std::sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return lines;
}

// The band [low, high] holding kBandShare of the power, widened to every
// spectral line; a tone when one line holds kToneShare and no other counts.
void classify_spectrum(const Eigen::VectorXd& x, double ts, ExcitedPart& p) {
  const std::vector<double> power = periodogram(x);
  const double df = 1.0 / (double(2 * (power.size() - 1)) * ts);
  double total = 0;
  for (std::size_t b = 1; b < power.size(); ++b) total += power[b];
  if (!(total > 0)) return;
  const auto reach = std::size_t(std::ceil(3.0 * double(2 * (power.size() - 1)) / double(x.size())));
  const auto lines = spectral_lines(power, total, reach, df);
  p.tone = lines.size() == 1 && lines[0].second >= kToneShare;
  double cumulative = 0;
  const double tail = 0.5 * (1 - kBandShare) * total;
  for (std::size_t b = 1; b < power.size(); ++b) {
    if (cumulative <= tail) p.low_hz = double(b) * df;
    cumulative += power[b];
    if (cumulative < total - tail) p.high_hz = double(b + 1) * df;
  }
  for (const auto& [hz, share] : lines) p.low_hz = std::min(p.low_hz, hz), p.high_hz = std::max(p.high_hz, hz);
  p.high_hz = std::max(p.high_hz, p.low_hz);
  p.frequency_hz = std::sqrt(p.low_hz * p.high_hz);
}

// A tone's frequency from the first and last of its zero crossings (about
// its mean): exact for whole half-periods whatever the record's ends do.
double tone_frequency(const Eigen::VectorXd& x, double ts) {
  const double mean = x.mean();
  Eigen::Index first = -1, last = -1;
  long crossings = 0;
  for (Eigen::Index k = 1; k < x.size(); ++k)
    if ((x[k - 1] - mean < 0) != (x[k] - mean < 0)) {
      if (first < 0) first = k;
      last = k;
      ++crossings;
    }
  if (crossings < 3) return std::nan("");
  return double(crossings - 1) / (2.0 * double(last - first) * ts);
}

ExcitedPart excited_part(const Eigen::VectorXd& u, const std::string& label, Eigen::Index begin,
                         Eigen::Index end, double ts) {
  ExcitedPart p{label, begin, end};
  const Eigen::VectorXd x = u.segment(begin, end - begin);
  classify_spectrum(x, ts, p);
  const double crossing = tone_frequency(x, ts);
  if (p.tone && std::isfinite(crossing)) p.frequency_hz = p.low_hz = p.high_hz = crossing;
  // Amplitudes over windows of the slowest period, so that every window
  // holds a whole cycle of what is slowest in the part.
  const double period = p.low_hz > 0 ? 1.0 / p.low_hz : double(end - begin) * ts;
  std::tie(p.amplitude_low, p.amplitude_high) = amplitude_range(x, Eigen::Index(std::round(period / ts)));
  p.periods = double(end - begin) * ts * p.frequency_hz;
  return p;
}

void add_run(ExcitationContent& e, const Eigen::VectorXd& u, const SegmentRun& run) {
  const double range = u.size() ? u.maxCoeff() - u.minCoeff() : 0.0;
  const auto rests = rests_of(u, run, e.sample_time, range, e.rests);
  Eigen::Index from = run.begin;
  const auto moving = [&](Eigen::Index to) {
    if (to - from >= 8) e.parts.push_back(excited_part(u, run.label, from, to, e.sample_time));
  };
  for (const auto& r : rests) {
    moving(r.begin);
    from = r.end;
  }
  moving(run.end);
  e.rests.insert(e.rests.end(), rests.begin(), rests.end());
}

std::vector<double> distinct(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x > kDistinctRatio * out.back()) out.push_back(x);
  return out;
}

void summarise(ExcitationContent& e) {
  std::vector<double> tones;
  bool first = true;
  for (const auto& p : e.parts) {
    if (p.tone) tones.push_back(p.frequency_hz);
    if (!(p.low_hz > 0)) continue;
    e.low_hz = first ? p.low_hz : std::min(e.low_hz, p.low_hz);
    e.high_hz = first ? p.high_hz : std::max(e.high_hz, p.high_hz);
    e.amplitude_low = first ? p.amplitude_low : std::min(e.amplitude_low, p.amplitude_low);
    e.amplitude_high = first ? p.amplitude_high : std::max(e.amplitude_high, p.amplitude_high);
    first = false;
  }
  e.tones_hz = distinct(tones);
}

std::string hz(double f) { return format_number("%.3g", f) + " Hz"; }

}  // namespace

ExcitationContent describe_excitation(const Eigen::VectorXd& u, const std::vector<std::string>& segment,
                               double sample_time, const std::string& u_unit) {
  ExcitationContent e;
  e.sample_time = sample_time > 0 ? sample_time : 1.0;
  e.u_unit = u_unit;
  for (const auto& run : segment_runs(segment, u.size())) add_run(e, u, run);
  summarise(e);
  return e;
}

bool ExcitationContent::meets(ExcitationNeed need) const {
  switch (need) {
    case ExcitationNeed::SeveralFrequencies: return low_hz > 0 && high_hz >= kFrequencySpan * low_hz;
    case ExcitationNeed::SeveralAmplitudes:
      return amplitude_low > 0 && amplitude_high >= kAmplitudeSpan * amplitude_low;
    case ExcitationNeed::HeldLevel:
      return std::any_of(rests.begin(), rests.end(), [&](const RestPart& r) {
        return r.after_change && double(r.end - r.begin) * sample_time >= kHeldLevelSeconds;
      });
  }
  return false;
}

double ExcitationContent::rest_seconds() const {
  double s = 0;
  for (const auto& r : rests) s += double(r.end - r.begin) * sample_time;
  return s;
}

std::string ExcitationContent::holds(ExcitationNeed need) const {
  const std::string unit = u_unit.empty() ? "" : " " + u_unit;
  switch (need) {
    case ExcitationNeed::SeveralFrequencies:
      return meets(need) ? "frequencies from " + hz(low_hz) + " to " + hz(high_hz)
                         : "one frequency (" + hz(std::sqrt(low_hz * high_hz)) + ")";
    case ExcitationNeed::SeveralAmplitudes:
      return meets(need) ? "amplitudes from " + format_number("%.3g", amplitude_low) + " to " +
                               format_number("%.3g", amplitude_high) + unit
                         : "one amplitude (" + format_number("%.3g", amplitude_high) + unit + ")";
    case ExcitationNeed::HeldLevel:
      return meets(need) ? "a held level after a change" : "no held input level after a change";
  }
  return "";
}

std::string ExcitationContent::summary() const {
  if (parts.empty()) return "The input never moves: the record excites nothing.";
  std::string f;
  if (!meets(ExcitationNeed::SeveralFrequencies))
    f = holds(ExcitationNeed::SeveralFrequencies);
  else if (tones_hz.size() > 1 && std::all_of(parts.begin(), parts.end(), [](const ExcitedPart& p) { return p.tone; }))
    f = std::to_string(tones_hz.size()) + " frequencies (" + hz(low_hz) + " to " + hz(high_hz) + ")";
  else
    f = "a band from " + hz(low_hz) + " to " + hz(high_hz);
  const std::string a = holds(ExcitationNeed::SeveralAmplitudes);
  double periods = 0;
  for (const auto& p : parts) periods += p.periods;
  std::string s = "The record excites " + f + " at " + a + ": " +
                  std::to_string(parts.size()) + (parts.size() == 1 ? " excited part" : " excited parts") +
                  " holding " + format_number("%.0f", periods) + " periods in all";
  if (!rests.empty())
    s += ", " + format_number("%.2g", rest_seconds()) + " s at rest in " + std::to_string(rests.size()) +
         (rests.size() == 1 ? " stretch" : " stretches");
  s += ".";
  return s;
}

nlohmann::json ExcitationContent::to_json() const {
  nlohmann::json p = nlohmann::json::array(), r = nlohmann::json::array();
  for (const auto& x : parts)
    p.push_back({{"segment", x.label},
                 {"begin", x.begin},
                 {"end", x.end},
                 {"tone", x.tone},
                 {"frequency_hz", x.frequency_hz},
                 {"low_hz", x.low_hz},
                 {"high_hz", x.high_hz},
                 {"amplitude_low", x.amplitude_low},
                 {"amplitude_high", x.amplitude_high},
                 {"periods", x.periods}});
  for (const auto& x : rests)
    r.push_back({{"begin", x.begin}, {"end", x.end}, {"level", x.level}, {"after_change", x.after_change}});
  return {{"summary", summary()},
          {"parts", p},
          {"rests", r},
          {"tones_hz", tones_hz},
          {"low_hz", low_hz},
          {"high_hz", high_hz},
          {"amplitude_low", amplitude_low},
          {"amplitude_high", amplitude_high},
          {"several_frequencies", meets(ExcitationNeed::SeveralFrequencies)},
          {"several_amplitudes", meets(ExcitationNeed::SeveralAmplitudes)},
          {"held_level", meets(ExcitationNeed::HeldLevel)}};
}

std::string need_text(ExcitationNeed need) {
  switch (need) {
    case ExcitationNeed::SeveralFrequencies: return "several frequencies";
    case ExcitationNeed::SeveralAmplitudes: return "several amplitudes";
    case ExcitationNeed::HeldLevel: return "a held input level after a change";
  }
  return "";
}

std::string excitation_advice(ExcitationNeed need) {
  switch (need) {
    case ExcitationNeed::SeveralFrequencies:
      return "record at least three frequencies over a decade (and two amplitudes)";
    case ExcitationNeed::SeveralAmplitudes:
      return "record at least two amplitudes, the larger at least 1.5 times the smaller";
    case ExcitationNeed::HeldLevel:
      return "record a step of the input held for several of the slowest time constants";
  }
  return "";
}

}  // namespace hystbench
