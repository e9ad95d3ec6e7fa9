#include "framework/io/excitation.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"

namespace hystbench {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct SegmentReader {
  const nlohmann::json& j;
  std::string where;

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) const {
    if (!j.contains(key)) {
      if (fallback) return *fallback;
      throw InputError(where + ": missing key \"" + key + "\"");
    }
    if (!j[key].is_number()) throw InputError(where + "." + key + ": expected a number, got " + j[key].dump());
    return j[key].get<double>();
  }
  double positive(const std::string& key) const {
    const double v = number(key);
    if (!(v > 0)) throw InputError(where + "." + key + " = " + j[key].dump() + ": must be positive");
    return v;
  }
  std::string label(const std::string& fallback) const { return j.value("label", fallback); }
};

std::string hz(double f) {
  std::ostringstream os;
  os << f;
  return os.str();
}

// Samples collect in std::vectors while segments are appended.
struct SignalBuilder {
  double sample_rate;
  std::vector<double> u;
  std::vector<std::string> segment;
};

void append(SignalBuilder& ex, double u, const std::string& label) {
  ex.u.push_back(u);
  ex.segment.push_back(label);
}

long samples(double duration, double fs) { return std::lround(duration * fs); }

void add_sine(SignalBuilder& ex, const SegmentReader& s) {
  require_known_keys(s.j, {"type", "frequency", "amplitude", "offset", "phase_deg", "duration", "label"}, s.where);
  const double f = s.positive("frequency"), a = s.number("amplitude"), off = s.number("offset", 0.0);
  const double phase = s.number("phase_deg", 0.0) * std::numbers::pi / 180.0;
  const std::string label = s.label("sine_" + hz(f) + "Hz");
  const long n = samples(s.positive("duration"), ex.sample_rate);
  for (long k = 0; k < n; ++k) append(ex, off + a * std::sin(kTwoPi * f * k / ex.sample_rate + phase), label);
}

void add_sweep(SignalBuilder& ex, const SegmentReader& s) {
  require_known_keys(s.j, {"type", "f0", "f1", "amplitude", "offset", "phase_deg", "duration", "label"}, s.where);
  const double f0 = s.positive("f0"), f1 = s.positive("f1"), T = s.positive("duration");
  const double a = s.number("amplitude"), off = s.number("offset", 0.0);
  const double phase = s.number("phase_deg", 0.0) * std::numbers::pi / 180.0;
  const std::string label = s.label("sweep_" + hz(f0) + "-" + hz(f1) + "Hz");
  const long n = samples(T, ex.sample_rate);
  for (long k = 0; k < n; ++k) {
    const double t = k / ex.sample_rate;  // linear chirp: phase integrates f0 + (f1 - f0) t / T
    append(ex, off + a * std::sin(kTwoPi * (f0 * t + (f1 - f0) * t * t / (2 * T)) + phase), label);
  }
}

// The sum of equal sines divided by their count, so `amplitude` bounds the
// excursion from `offset` (seed 002's compound test signals).
void add_multisine(SignalBuilder& ex, const SegmentReader& s) {
  require_known_keys(s.j, {"type", "frequencies", "amplitude", "offset", "phase_deg", "duration", "label"}, s.where);
  std::vector<double> f;
  if (s.j.contains("frequencies") && s.j["frequencies"].is_array())
    for (const auto& v : s.j["frequencies"])
      if (v.is_number() && v.get<double>() > 0) f.push_back(v.get<double>());
  if (f.empty() || f.size() != s.j["frequencies"].size())
    throw InputError(s.where + ".frequencies: expected a non-empty list of positive frequencies in Hz");
  const double a = s.number("amplitude") / double(f.size()), off = s.number("offset", 0.0);
  const double phase = s.number("phase_deg", 0.0) * std::numbers::pi / 180.0;
  std::string name;
  for (double fi : f) name.append(name.empty() ? "" : "/").append(hz(fi));
  const std::string label = s.label("multisine_" + name + "Hz");
  const long n = samples(s.positive("duration"), ex.sample_rate);
  for (long k = 0; k < n; ++k) {
    double sum = 0.0;
    for (double fi : f) sum += std::sin(kTwoPi * fi * k / ex.sample_rate + phase);
    append(ex, off + a * sum, label);
  }
}

void add_steps(SignalBuilder& ex, const SegmentReader& s) {
  require_known_keys(s.j, {"type", "levels", "hold", "ramp", "label"}, s.where);
  if (!s.j.contains("levels") || !s.j["levels"].is_array() || s.j["levels"].empty())
    throw InputError(s.where + ".levels: expected a non-empty list of input levels");
  const double hold = s.positive("hold"), ramp = s.number("ramp", 0.0);
  const std::string label = s.label("steps");
  double from = ex.u.empty() ? 0.0 : ex.u.back();
  for (const auto& level_json : s.j["levels"]) {
    if (!level_json.is_number()) throw InputError(s.where + ".levels: " + level_json.dump() + " is not a number");
    const double level = level_json.get<double>();
    const long nr = samples(ramp, ex.sample_rate);
    for (long k = 1; k <= nr; ++k) append(ex, from + (level - from) * double(k) / double(nr), label);
    for (long k = 0; k < samples(hold, ex.sample_rate); ++k) append(ex, level, label);
    from = level;
  }
}

}  // namespace

Excitation make_excitation(const nlohmann::json& spec) {
  require_known_keys(spec, {"sample_rate", "segments"}, "excitation");
  SignalBuilder ex{SegmentReader{spec, "excitation"}.positive("sample_rate"), {}, {}};
  if (!spec.contains("segments") || !spec["segments"].is_array() || spec["segments"].empty())
    throw InputError("excitation.segments: expected a non-empty list of segments");
  for (std::size_t i = 0; i < spec["segments"].size(); ++i) {
    const auto& seg = spec["segments"][i];
    const SegmentReader reader{seg, "excitation.segments[" + std::to_string(i) + "]"};
    const std::string type = seg.is_object() ? seg.value("type", "") : "";
    if (type == "sine") add_sine(ex, reader);
    else if (type == "sweep") add_sweep(ex, reader);
    else if (type == "multisine") add_multisine(ex, reader);
    else if (type == "steps") add_steps(ex, reader);
    else throw InputError(reader.where + ".type: expected \"sine\", \"sweep\", \"multisine\" or \"steps\"");
  }
  Excitation out{ex.sample_rate, Eigen::VectorXd(ex.u.size()),
                 Eigen::Map<const Eigen::VectorXd>(ex.u.data(), ex.u.size()), std::move(ex.segment)};
  for (Eigen::Index k = 0; k < out.t.size(); ++k) out.t[k] = double(k) / out.sample_rate;
  return out;
}

}  // namespace hystbench
