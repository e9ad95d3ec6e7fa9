#include "framework/tracking/tracking_experiment.hpp"

#include <cmath>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/text.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/json_file.hpp"
#include "framework/control/model_stream.hpp"

namespace hystbench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

nlohmann::json object_at(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const nlohmann::json v = j.value(key, nlohmann::json::object());
  if (!v.is_object()) throw InputError(where + "." + key + ": expected an object");
  return v;
}

std::vector<double> coefficients(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const nlohmann::json c = j.value(key, nlohmann::json());
  if (!c.is_array() || c.empty())
    throw InputError(where + "." + key + ": give the coefficients in s, highest power first, e.g. [0.08, 4.4]");
  std::vector<double> out;
  for (const auto& v : c) {
    if (!v.is_number()) throw InputError(where + "." + key + ": coefficients must be numbers");
    out.push_back(v.get<double>());
  }
  return out;
}

UncertaintySpec read_uncertainty(const nlohmann::json& j, const std::filesystem::path& base, const std::string& where) {
  require_known_keys(j, {"weight", "records", "margin", "rise", "num", "den"}, where);
  UncertaintySpec u;
  u.kind = optional_text(j, "weight", "residual", where);
  if (u.kind != "seed" && u.kind != "residual" && u.kind != "given")
    throw InputError(where + ".weight: \"residual\" (from the identification residual over the records), "
                             "\"seed\" (seed 002's eq. 21) or \"given\" (num and den), not \"" + u.kind + "\"");
  u.margin = optional_number(j, "margin", 2.0, 1.0, 1e6, where);
  u.rise = optional_number(j, "rise", 4.0, 1.0, 1e6, where);
  if (u.kind == "given") {
    u.num = coefficients(j, "num", where);
    u.den = coefficients(j, "den", where);
  }
  if (u.kind != "residual") return u;
  const nlohmann::json records = j.value("records", nlohmann::json());
  if (!records.is_array() || records.empty())
    throw InputError(where + ".records: give the measurement files whose residual bounds the uncertainty, "
                             "or \"weight\": \"seed\"");
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string at = where + ".records[" + std::to_string(i) + "]";
    if (!records[i].is_string()) throw InputError(at + ": expected a file name");
    u.records.push_back(resolve_data_path(records[i].get<std::string>(), base, at));
  }
  return u;
}

DesignOptions read_design(const nlohmann::json& j, const std::string& where) {
  DesignOptions d;
  const nlohmann::json perf = object_at(j, "performance", where);
  require_known_keys(perf, {"bandwidth_hz", "peak", "low_frequency_error"}, where + ".performance");
  d.performance.bandwidth_hz = optional_number(perf, "bandwidth_hz", 100.0, 1e-3, 1e6, where + ".performance");
  d.performance.peak = optional_number(perf, "peak", 2.0, 1.0, 1e3, where + ".performance");
  d.performance.low_frequency_error =
      optional_number(perf, "low_frequency_error", 1e-4, 1e-12, 0.5, where + ".performance");
  const nlohmann::json red = object_at(j, "reduction", where);
  require_known_keys(red, {"method", "order"}, where + ".reduction");
  d.reduction = optional_text(red, "method", "stochastic", where + ".reduction");
  if (d.reduction != "stochastic" && d.reduction != "balanced")
    throw InputError(where + ".reduction.method: \"stochastic\" (AB09HD, MATLAB's bstmr) or \"balanced\" "
                             "(AB09AD), not \"" + d.reduction + "\"");
  d.reduced_order = int(optional_number(red, "order", 3, 1, 50, where + ".reduction"));
  return d;
}

TrackingController read_controller(const nlohmann::json& c, const std::string& where) {
  if (!c.is_object()) throw InputError(where + ": expected an object with \"type\"");
  require_known_keys(c, {"label", "type", "order", "kp", "ki"}, where);
  TrackingController t;
  const std::string type = optional_text(c, "type", "", where);
  t.label = optional_text(c, "label", type, where);
  if (type == "inverse_only") {
    t.kind = TrackingController::Kind::InverseOnly;
  } else if (type == "hinf_2dof") {
    t.kind = TrackingController::Kind::Hinf;
    t.order = optional_text(c, "order", "reduced", where);
    if (t.order != "full" && t.order != "reduced")
      throw InputError(where + ".order: \"full\" or \"reduced\", not \"" + t.order + "\"");
  } else if (type == "pi") {
    t.kind = TrackingController::Kind::Pi;
    t.kp = optional_number(c, "kp", 0.0, 0.0, 1e6, where);
    t.ki = optional_number(c, "ki", 0.0, 0.0, 1e9, where);
  } else {
    throw InputError(where + ".type: \"inverse_only\", \"hinf_2dof\" or \"pi\", not \"" + type + "\"");
  }
  return t;
}

// A signal: 10, [10, 20, 40], or {"hz": .., "amplitude": .., "offset": ..}
// overriding the block's amplitude and offset.
TrackingReference read_signal(const nlohmann::json& s, double amplitude, double offset, const std::string& where) {
  nlohmann::json hz = s;
  if (s.is_object()) {
    require_known_keys(s, {"hz", "amplitude", "offset"}, where);
    hz = s.value("hz", nlohmann::json());
    amplitude = optional_number(s, "amplitude", amplitude, 0.0, kInf, where);
    offset = optional_number(s, "offset", offset, -kInf, kInf, where);
  }
  if (!hz.is_array()) hz = nlohmann::json::array({hz});
  std::vector<double> frequencies;
  for (const auto& f : hz) {
    if (!f.is_number()) throw InputError(where + ": frequencies must be numbers (Hz)");
    frequencies.push_back(f.get<double>());
  }
  return make_reference(frequencies, amplitude, offset, where);
}

// The label names the amplitude and offset a signal sets for itself:
// "10 Hz amplitude 15 offset 15".
void read_references(const nlohmann::json& j, TrackingExperiment& x, const std::string& where) {
  require_known_keys(j, {"amplitude", "offset", "signals"}, where);
  const double amplitude = optional_number(j, "amplitude", 15.0, 0.0, kInf, where);
  const double offset = optional_number(j, "offset", amplitude, -kInf, kInf, where);
  const nlohmann::json signals = j.value("signals", nlohmann::json());
  if (!signals.is_array() || signals.empty())
    throw InputError(where + ".signals: give a list of signals, each a frequency in Hz or a list of them");
  for (std::size_t i = 0; i < signals.size(); ++i) {
    x.references.push_back(read_signal(signals[i], amplitude, offset, where + ".signals[" + std::to_string(i) + "]"));
    TrackingReference& r = x.references.back();
    if (r.amplitude != amplitude) r.label += " amplitude " + format_number("%g", r.amplitude);
    if (r.offset != offset) r.label += " offset " + format_number("%g", r.offset);
    for (std::size_t k = 0; k + 1 < x.references.size(); ++k)
      if (x.references[k].label == r.label)
        throw InputError(where + ".signals[" + std::to_string(i) + "]: \"" + r.label +
                         "\" again; every signal is one table row and figure, so give each its own "
                         "frequencies, amplitude or offset");
    for (double f : r.hz)
      if (f >= 0.25 / x.sample_time)
        throw InputError(where + ".signals[" + std::to_string(i) + "]: " + format_number("%g", f) +
                         " Hz is not below a quarter of the sampling rate (" +
                         format_number("%g", 0.25 / x.sample_time) + " Hz)");
  }
}

// The simulated plant, its sensor and amplifier; the plant is built once
// here so that a bad parameter stops the command before anything is written.
void read_plant(const nlohmann::json& j, TrackingExperiment& x, const std::string& where) {
  x.plant = object_at(j, "plant", where);
  require_known_keys(x.plant, model_stream_keys(), where + ".plant");
  x.plant_description = model_stream(x.plant, x.base_dir, x.sample_time, where + ".plant").description;
  const nlohmann::json sensor = object_at(j, "sensor", where);
  require_known_keys(sensor, {"noise_sd", "resolution"}, where + ".sensor");
  x.sensor = {optional_number(sensor, "noise_sd", 0.0, 0.0, kInf, where + ".sensor"),
              optional_number(sensor, "resolution", 0.0, 0.0, kInf, where + ".sensor")};
  const nlohmann::json amp = object_at(j, "amplifier", where);
  require_known_keys(amp, {"min", "max"}, where + ".amplifier");
  x.u_min = optional_number(amp, "min", 0.0, -kInf, kInf, where + ".amplifier");
  x.u_max = optional_number(amp, "max", 150.0, -kInf, kInf, where + ".amplifier");
  if (!(x.u_min < x.u_max)) throw InputError(where + ".amplifier: needs min < max");
}

int order(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const double v = optional_number(j, key, key == "p" ? 2 : 1, 1, 8, where);
  if (v != std::floor(v)) throw InputError(where + "." + key + ": give a whole number from 1 to 8");
  return int(v);
}

// The identified model at the loop's rate, and the orders of its L(z).
void read_models(const nlohmann::json& j, TrackingExperiment& x, const std::string& where) {
  const nlohmann::json identified = object_at(j, "identified", where);
  std::vector<std::string> keys = model_stream_keys();
  keys.push_back("svr");
  require_known_keys(identified, keys, where + ".identified");
  x.identified = read_identified(identified, x.base_dir, where + ".identified");
  x.identified_model = x.identified.make(x.sample_time);
  const nlohmann::json nominal = object_at(j, "nominal", where);
  require_known_keys(nominal, {"p", "q"}, where + ".nominal");
  x.p = order(nominal, "p", where + ".nominal");
  x.q = order(nominal, "q", where + ".nominal");
}

// Runs longer than this many samples are refused: every run keeps its
// signals (three doubles a sample) for the figures.
constexpr double kMaxRunSamples = 1e7;

void read_window(const nlohmann::json& j, TrackingExperiment& x, const std::string& where) {
  const nlohmann::json window = object_at(j, "window", where);
  require_known_keys(window, {"settle_s", "length_s"}, where + ".window");
  x.window = {optional_number(window, "settle_s", 0.2, 0.0, 1e4, where + ".window"),
              optional_number(window, "length_s", 0.1, 0.0, 1e4, where + ".window")};
  for (const TrackingReference& r : x.references) {
    const WindowSamples w = window_samples(r, x.window, x.sample_time);
    if (double(w.end()) > kMaxRunSamples)
      throw InputError(where + ".references: " + r.label + " needs " + format_number("%.3g", double(w.end())) +
                       " samples (its common period is " + format_number("%g", 1.0 / r.fundamental_hz) +
                       " s); keep a run below 1e7 samples: frequencies with a larger common divisor, or a "
                       "shorter window");
  }
}

}  // namespace

TrackingExperiment TrackingExperiment::load(const std::filesystem::path& path) {
  return from_json(read_json_file(path, "tracking experiment"), path.parent_path(), path.string());
}

TrackingExperiment TrackingExperiment::from_json(const nlohmann::json& j, const std::filesystem::path& base,
                                                 const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": expected a JSON object");
  require_known_keys(j, {"name", "description", "sample_rate", "plant", "sensor", "amplifier", "identified",
                         "nominal", "uncertainty", "performance", "reduction", "controllers", "references",
                         "window", "inverse_tolerance", "units", "seed", "records"},
                     where);
  TrackingExperiment x;
  x.source = j;
  x.base_dir = base;
  x.name = optional_text(j, "name", "tracking", where);
  x.description = optional_text(j, "description", "", where);
  x.sample_time = 1.0 / optional_number(j, "sample_rate", 10000.0, 1.0, 1e7, where);
  read_plant(j, x, where);
  read_models(j, x, where);
  x.uncertainty = read_uncertainty(object_at(j, "uncertainty", where), base, where + ".uncertainty");
  x.design = read_design(j, where);
  const nlohmann::json controllers = j.value("controllers", nlohmann::json());
  if (!controllers.is_array() || controllers.empty())
    throw InputError(where + ".controllers: give a list of controllers ({\"type\": \"hinf_2dof\"}, ...)");
  for (std::size_t i = 0; i < controllers.size(); ++i)
    x.controllers.push_back(read_controller(controllers[i], where + ".controllers[" + std::to_string(i) + "]"));
  const nlohmann::json units = object_at(j, "units", where);
  require_known_keys(units, {"u", "y"}, where + ".units");
  x.u_unit = optional_text(units, "u", "V", where + ".units");
  x.y_unit = optional_text(units, "y", "µm", where + ".units");
  read_references(object_at(j, "references", where), x, where + ".references");
  read_window(j, x, where);
  x.inverse_tolerance = optional_number(j, "inverse_tolerance", 1e-6, 1e-15, 1e3, where);
  x.seed = std::uint64_t(optional_number(j, "seed", 1, 0, 9e15, where));
  return x;
}

}  // namespace hystbench
