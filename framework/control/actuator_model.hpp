#pragma once
// An actuator model in volts (docs/control.md#actuator-in-the-control-path):
// a model as model_stream.hpp reads it, plus
//
//   "input_scale": s    the model sees input_offset + s u (default 1)
//   "input_offset": b   (default 0; a biased drive, as identification data often have)
//   "unit_gain": true   divide the output by the model's first-harmonic gain
//                       for the disturbance's sine (amplitude a at f0), so the
//                       model adds harmonics and phase but no gain at f0
//
// The plant's actuator and an identified estimate of it read the same keys.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/control/control_loop.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

struct ActuatorModel {
  std::unique_ptr<SignalStream> stream;
  std::string description;
  double gain_divided_out = 1.0;
};

// model_stream_keys() and the three above.
std::vector<std::string> actuator_model_keys();

// Throws InputError naming `where` and the key.
ActuatorModel actuator_model(const nlohmann::json& spec, const LoopSettings& loop,
                             const std::filesystem::path& base_dir, const std::string& where);

}  // namespace hystbench
