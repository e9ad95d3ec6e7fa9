#include "framework/control/actuator_model.hpp"

#include <cmath>

#include "framework/control/first_harmonic.hpp"
#include "framework/control/model_stream.hpp"
#include "framework/control/scaled_stream.hpp"
#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
std::vector<std::string> actuator_model_keys() {
  auto keys = model_stream_keys();
  keys.insert(keys.end(), {"input_scale", "input_offset", "unit_gain"});
  return keys;
}

ActuatorModel actuator_model(const nlohmann::json& spec, const LoopSettings& loop,
                             const std::filesystem::path& base_dir, const std::string& where) {
  require_known_keys(spec, actuator_model_keys(), where);
  const double scale = optional_number(spec, "input_scale", 1.0, -1e12, 1e12, where);
  const double offset = optional_number(spec, "input_offset", 0.0, -1e12, 1e12, where);
  const bool unit_gain = optional_flag(spec, "unit_gain", true, where);
  nlohmann::json model = spec;
  for (const char* key : {"input_scale", "input_offset", "unit_gain"}) model.erase(key);
  ModelStream m = model_stream(model, base_dir, 1.0 / loop.sample_rate_hz, where);
  ActuatorModel a;
  auto scaled = std::make_unique<ScaledStream>(std::move(m.stream), scale, 1.0, offset);
  a.description = m.description;
  if (scale != 1.0 || offset != 0.0)
    a.description += ", input " + (offset != 0.0 ? number_text(offset) + " + " : "") +
                     number_text(scale) + " u";
  if (unit_gain) {
    a.gain_divided_out =
        std::abs(first_harmonic(*scaled, probe_at(loop, loop.disturbance_amplitude)));
    if (!(a.gain_divided_out > 0.0) || !std::isfinite(a.gain_divided_out))
      throw InputError(where + ": the model gives no first harmonic at " +
                       number_text(loop.disturbance_hz) + " Hz; check its parameters");
    scaled->set_output_scale(1.0 / a.gain_divided_out);
  }
  a.stream = std::move(scaled);
  return a;
}

}  // namespace hystbench
