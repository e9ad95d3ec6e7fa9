#include "framework/control/actuator_model.hpp"

#include <cmath>

#include "framework/control/first_harmonic.hpp"
#include "framework/control/model_stream.hpp"
#include "framework/control/scaled_stream.hpp"
#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

double real_key(const nlohmann::json& spec, const std::string& key, double fallback,
                const std::string& where) {
  if (!spec.contains(key)) return fallback;
  if (!spec[key].is_number()) throw InputError(where + "." + key + ": give a number");
  return spec[key].get<double>();
}

}  // namespace

std::vector<std::string> actuator_model_keys() {
  auto keys = model_stream_keys();
  keys.insert(keys.end(), {"input_scale", "input_offset", "unit_gain"});
  return keys;
}

ActuatorModel actuator_model(const nlohmann::json& spec, const LoopSettings& loop,
                             const std::filesystem::path& base_dir, const std::string& where) {
  require_known_keys(spec, actuator_model_keys(), where);
  const double scale = real_key(spec, "input_scale", 1.0, where);
  const double offset = real_key(spec, "input_offset", 0.0, where);
  if (spec.contains("unit_gain") && !spec["unit_gain"].is_boolean())
    throw InputError(where + ".unit_gain: give true or false");
  nlohmann::json model = spec;
  for (const char* key : {"input_scale", "input_offset", "unit_gain"}) model.erase(key);
  ModelStream m = model_stream(model, base_dir, 1.0 / loop.sample_rate_hz, where);
  ActuatorModel a;
  a.stream = std::make_unique<ScaledStream>(std::move(m.stream), scale, 1.0, offset);
  a.description = m.description;
  if (scale != 1.0 || offset != 0.0)
    a.description += ", input " + (offset != 0.0 ? number_text(offset) + " + " : "") +
                     number_text(scale) + " u";
  if (spec.value("unit_gain", true)) {
    HarmonicProbe probe;
    probe.hz = loop.disturbance_hz;
    probe.amplitude = loop.disturbance_amplitude;
    probe.sample_rate_hz = loop.sample_rate_hz;
    a.gain_divided_out = std::abs(first_harmonic(*a.stream, probe));
    if (!(a.gain_divided_out > 0.0) || !std::isfinite(a.gain_divided_out))
      throw InputError(where + ": the model gives no first harmonic at " +
                       number_text(loop.disturbance_hz) + " Hz; check its parameters");
    a.stream = std::make_unique<ScaledStream>(std::move(a.stream), 1.0, 1.0 / a.gain_divided_out);
  }
  return a;
}

}  // namespace hystbench
