#pragma once
// A control experiment file (docs/control.md#experiment-file): the plant,
// the actuator in its control path, the disturbance, the secondary-path
// estimate, the controllers to compare and a sweep of fixed steps, the
// duration and the trials. Everything is checked when it is read, so a bad
// file stops the command (exit 2) before anything is written.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/control/control_loop.hpp"
#include "framework/control/control_metrics.hpp"
#include "framework/control/controller.hpp"

namespace hystbench {

struct ControllerEntry {
  std::string label;
  std::string name;      // registry key
  Params params;         // validated, defaults filled in
  bool reconstructed = false;
  bool in_sweep = false;  // one point of the fixed-step sweep
  double sweep_value = 0.0;
  nlohmann::json secondary;  // its own estimate; null: the experiment's
  std::string where;         // "exp.json.controllers[2]", for messages

  std::unique_ptr<Controller> make() const;
};

struct ControlExperiment {
  std::string name, description;
  LoopSettings loop;  // noise_sd and divergence_level are set by the setup
  MetricWindows windows;
  double snr_db = 30.0;
  double divergence_ratio = 2.0;  // divergence level / uncontrolled steady RMS
  nlohmann::json plant, actuator, secondary;  // checked by the setup
  std::vector<ControllerEntry> controllers;   // compared ones first, then the sweep
  std::string sweep_param;                    // e.g. "mu"; empty without a sweep
  int trials = 5;
  std::uint64_t seed = 1;
  std::filesystem::path base_dir;
  nlohmann::json source;  // the file as read

  // Throws InputError naming the file and the key.
  static ControlExperiment load(const std::filesystem::path& file);
  static ControlExperiment from_json(const nlohmann::json& j, const std::string& where);
};

}  // namespace hystbench
