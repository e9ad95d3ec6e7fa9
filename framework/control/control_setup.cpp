#include "framework/control/control_setup.hpp"

#include <cmath>

#include "framework/control/actuator_model.hpp"
#include "framework/control/scaled_stream.hpp"
#include "framework/control/uncontrolled.hpp"
#include "framework/core/error.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {
namespace {

std::unique_ptr<Plant> make_plant(const ControlExperiment& x) {
  const std::string where = "plant";
  if (!x.plant.is_object() || !x.plant.contains("type") || !x.plant["type"].is_string())
    throw InputError(where + ".type: give a plant name (hystbench list plants)");
  require_known_keys(x.plant, {"type", "params"}, where);
  const PlantInfo& info = PlantRegistry::instance().find(x.plant["type"], where + ".type");
  const Params p =
      validate_params(info.params, x.plant.value("params", nlohmann::json::object()), where + ".params");
  return info.create(p, {x.loop.sample_rate_hz, x.loop.disturbance_hz, x.loop.disturbance_amplitude});
}

void add_actuator(const ControlExperiment& x, ControlSetup& s) {
  s.paths.control = s.plant->control_path();
  s.actuator = "none (linear control path)";
  if (x.actuator.is_null()) return;
  ActuatorModel a = actuator_model(x.actuator, x.loop, x.base_dir, "actuator");
  s.actuator = a.description;
  s.actuator_gain = a.gain_divided_out;
  s.paths.control = std::make_unique<SeriesStream>(std::move(a.stream), std::move(s.paths.control));
}

// The steady RMS of the noise-free uncontrolled error (the control path at
// u = 0 included: an actuator model may answer a zero input).
double uncontrolled_rms(const ControlSetup& s, const ControlExperiment& x) {
  LoopSettings quiet = s.loop;
  quiet.noise_sd = 0.0;
  const LoopTrace t = run_uncontrolled(s.paths, quiet, 0);
  const double rms = steady_rms(t.true_error, x.windows);
  if (!(rms > 0.0) || !std::isfinite(rms))
    throw InputError("disturbance: the uncontrolled error has RMS " + std::to_string(rms) +
                     " over the steady window; the plant must respond to the disturbance");
  return rms;
}

// The experiment's estimate first, then each distinct one a controller names.
void add_estimates(const ControlExperiment& x, ControlSetup& s) {
  const EstimateContext context{*s.plant, *s.paths.control, s.loop,
                                trial_seed(x.seed, "secondary path identification", 0), x.base_dir};
  std::vector<nlohmann::json> specs{x.secondary};
  s.estimates.push_back(secondary_path(x.secondary, context, "secondary"));
  for (std::size_t c = 0; c < x.controllers.size(); ++c) {
    const nlohmann::json& spec = x.controllers[c].secondary;
    std::size_t i = 0;
    if (!spec.is_null()) {
      while (i < specs.size() && specs[i] != spec) ++i;
      if (i == specs.size()) {
        specs.push_back(spec);
        s.estimates.push_back(secondary_path(spec, context, x.controllers[c].where + ".secondary"));
      }
    }
    s.estimate_of.push_back(int(i));
  }
}

}  // namespace

ControlSetup build_control_setup(const ControlExperiment& x) {
  ControlSetup s;
  s.plant = make_plant(x);
  s.loop = x.loop;
  s.paths.disturbance = s.plant->disturbance_path();
  add_actuator(x, s);
  s.uncontrolled_rms = uncontrolled_rms(s, x);
  s.loop.noise_sd = s.uncontrolled_rms * std::pow(10.0, -x.snr_db / 20.0);
  s.loop.divergence_level = x.divergence_ratio * s.uncontrolled_rms;
  s.loop.uncontrolled_level = s.uncontrolled_rms;
  add_estimates(x, s);
  return s;
}

nlohmann::json ControlSetup::to_json() const {
  nlohmann::json estimates_json = nlohmann::json::array();
  for (const auto& e : estimates)
    estimates_json.push_back({{"estimate", e.description},
                              {"phase_error_deg", e.error.phase_deg},
                              {"gain_ratio", e.error.gain_ratio}});
  return {{"plant", plant->details()},
          {"actuator", {{"model", actuator}, {"first_harmonic_gain_divided_out", actuator_gain}}},
          {"secondary_estimates", estimates_json},
          {"uncontrolled_true_rms", uncontrolled_rms},
          {"sensor_noise_sd", loop.noise_sd},
          {"divergence_level", loop.divergence_level}};
}

}  // namespace hystbench
