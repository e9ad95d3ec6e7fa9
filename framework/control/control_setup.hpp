#pragma once
// Everything an experiment's runs share, built once from the experiment
// (docs/control.md#the-loop): the plant, the actuator model in front of its
// control path, the secondary-path estimates (the experiment's, and any a
// controller names for itself) with their error at the disturbance, the
// noise level and the divergence level.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/control/control_experiment.hpp"
#include "framework/control/control_loop.hpp"
#include "framework/control/plant.hpp"
#include "framework/control/secondary_path.hpp"

namespace hystbench {

struct ControlSetup {
  std::unique_ptr<Plant> plant;
  LoopPaths paths;
  LoopSettings loop;     // the experiment's, with noise_sd and divergence_level set
  std::string actuator;  // description
  double actuator_gain = 1.0;  // first-harmonic gain divided out (1 without)
  double uncontrolled_rms = 0.0;  // steady RMS of the noise-free uncontrolled error
  std::vector<SecondaryPath> estimates;  // distinct estimates, the experiment's first
  std::vector<int> estimate_of;          // per controller of the experiment

  const SecondaryPath& estimate_for(std::size_t controller) const {
    return estimates[estimate_of[controller]];
  }
  nlohmann::json to_json() const;
};

// Throws InputError naming the key.
ControlSetup build_control_setup(const ControlExperiment& x);

}  // namespace hystbench
