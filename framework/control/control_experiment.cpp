#include "framework/control/control_experiment.hpp"

#include <algorithm>
#include <fstream>
#include <set>

#include "framework/core/error.hpp"
#include "framework/io/json_file.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

nlohmann::json object_or_empty(const nlohmann::json& j, const std::string& key,
                               const std::string& where) {
  if (!j.contains(key)) return nlohmann::json::object();
  if (!j[key].is_object()) throw InputError(where + "." + key + ": give an object {...}");
  return j[key];
}

ControllerEntry controller_entry(const nlohmann::json& c, const std::string& where) {
  require_known_keys(c, {"label", "name", "params", "secondary"}, where);
  if (!c.contains("name") || !c["name"].is_string())
    throw InputError(where + ".name: give a controller name (hystbench list controllers)");
  ControllerEntry e;
  e.name = c["name"].get<std::string>();
  const ControllerInfo& info = ControllerRegistry::instance().find(e.name, where + ".name");
  e.label = optional_text(c, "label", e.name, where);
  e.params = validate_params(info.params, c.value("params", nlohmann::json::object()),
                             where + ".params");
  e.reconstructed = info.reconstructed;
  e.secondary = c.value("secondary", nlohmann::json());
  e.where = where;
  try {
    e.make();  // a plugin's own checks (e.g. mu_min <= mu_max) fail here, before any output
  } catch (const InputError& err) {
    throw InputError(where + "." + err.what());
  }
  return e;
}

void read_controllers(const nlohmann::json& j, const std::string& where, ControlExperiment& x) {
  if (!j.contains("controllers") || !j["controllers"].is_array() || j["controllers"].empty())
    throw InputError(where + ".controllers: give a list of {\"label\", \"name\", \"params\"}");
  std::set<std::string> labels;
  for (std::size_t i = 0; i < j["controllers"].size(); ++i) {
    const std::string at = where + ".controllers[" + std::to_string(i) + "]";
    ControllerEntry e = controller_entry(j["controllers"][i], at);
    if (!labels.insert(e.label).second)
      throw InputError(at + ".label: '" + e.label + "' is used twice; labels must be unique");
    x.controllers.push_back(std::move(e));
  }
}

// "step_sweep": {"name": "fxnlms", "param": "mu", "values": [...], "params": {...}}
void read_sweep(const nlohmann::json& s, const std::string& where, ControlExperiment& x) {
  require_known_keys(s, {"name", "param", "values", "params"}, where);
  x.sweep_param = optional_text(s, "param", "mu", where);
  const std::string name = optional_text(s, "name", "", where);
  const ControllerInfo& info = ControllerRegistry::instance().find(name, where + ".name");
  const auto spec = std::find_if(info.params.begin(), info.params.end(),
                                 [&](const ParamSpec& p) { return p.name == x.sweep_param; });
  if (spec == info.params.end() || spec->type == ParamSpec::Type::Choice ||
      spec->type == ParamSpec::Type::Boolean)
    throw InputError(where + ".param: '" + x.sweep_param + "' is not a numeric parameter of " + name +
                     " (hystbench list controllers)");
  if (!s.contains("values") || !s["values"].is_array() || s["values"].empty())
    throw InputError(where + ".values: give a list of " + x.sweep_param + " values");
  for (std::size_t i = 0; i < s["values"].size(); ++i) {
    nlohmann::json params = s.value("params", nlohmann::json::object());
    params[x.sweep_param] = s["values"][i];
    const nlohmann::json c = {{"name", name}, {"params", params}};
    ControllerEntry e = controller_entry(c, where + ".values[" + std::to_string(i) + "]");
    e.in_sweep = true;
    e.sweep_value = e.params.real(x.sweep_param);
    e.label = x.sweep_param + " = " + number_text(e.sweep_value);
    x.controllers.push_back(std::move(e));
  }
}

}  // namespace

std::unique_ptr<Controller> ControllerEntry::make() const {
  return ControllerRegistry::instance().find(name, "controller").create(params);
}

ControlExperiment ControlExperiment::load(const std::filesystem::path& file) {
  ControlExperiment x = from_json(read_json_file(file, "experiment file"), file.string());
  x.base_dir = file.parent_path();
  return x;
}

ControlExperiment ControlExperiment::from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": the experiment must be a JSON object");
  require_known_keys(j, {"name", "description", "sample_rate_hz", "duration_s", "steady_s",
                         "disturbance", "plant", "actuator", "noise", "secondary",
                         "controllers", "step_sweep", "divergence_ratio", "trials", "seed"},
                     where);
  ControlExperiment x;
  x.source = j;
  x.name = optional_text(j, "name", "control", where);
  x.description = optional_text(j, "description", "", where);
  x.loop.sample_rate_hz = optional_number(j, "sample_rate_hz", 1000.0, 10.0, 1e7, where);
  // At least 1 s: convergence and divergence are judged on a 1 s moving RMS.
  x.loop.duration_s = optional_number(j, "duration_s", 60.0, 1.0, 1e5, where);
  x.windows = {x.loop.sample_rate_hz, optional_number(j, "steady_s", std::min(10.0, x.loop.duration_s),
                                                      1.0, x.loop.duration_s, where)};
  const nlohmann::json d = object_or_empty(j, "disturbance", where);
  require_known_keys(d, {"frequency_hz", "amplitude"}, where + ".disturbance");
  // At least one whole period in the 10 s over which responses are measured.
  x.loop.disturbance_hz = optional_number(d, "frequency_hz", 20.61, 0.1,
                                          x.loop.sample_rate_hz / 2, where + ".disturbance");
  x.loop.disturbance_amplitude =
      optional_number(d, "amplitude", 3.0, 1e-12, 1e12, where + ".disturbance");
  if (!(x.loop.disturbance_hz < x.loop.sample_rate_hz / 2))
    throw InputError(where + ".disturbance.frequency_hz: " + number_text(x.loop.disturbance_hz) +
                     " Hz is not below half the sampling rate (" +
                     number_text(x.loop.sample_rate_hz / 2) + " Hz)");
  const nlohmann::json noise = object_or_empty(j, "noise", where);
  require_known_keys(noise, {"snr_db"}, where + ".noise");
  x.snr_db = optional_number(noise, "snr_db", 30.0, -100.0, 400.0, where + ".noise");
  x.divergence_ratio = optional_number(j, "divergence_ratio", 2.0, 1.0, 1e12, where);
  x.plant = j.value("plant", nlohmann::json{{"type", "mfc_beam"}});
  x.actuator = j.value("actuator", nlohmann::json());
  x.secondary = j.value("secondary", nlohmann::json{{"type", "linear_true"}});
  x.trials = int(optional_number(j, "trials", 5, 1, 100000, where));
  x.seed = std::uint64_t(optional_number(j, "seed", 1, 0, 9007199254740992.0, where));
  read_controllers(j, where, x);
  if (j.contains("step_sweep")) read_sweep(j["step_sweep"], where + ".step_sweep", x);
  return x;
}

}  // namespace hystbench
