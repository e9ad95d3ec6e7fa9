#pragma once
// A hystbench model as a stream in physical units, as an experiment names it
// (docs/control.md#models-in-the-loop):
//
//   {"fit": "fit.json"}                      a model from `hystbench fit` / `discover`
//   {"model": "hysteresis,asymmetry",        an effect list with the physical value of
//    "parameters": {"gain": .., ...},        every parameter (or a JSON file of them), in the units of `scales`
//    "scales": {"u": 1, "y": 1}}             (optional; 1 and 1 by default)
//
// and optionally "input_hold": "linear" (default) or "zoh", how its ODE
// effects see the input between samples (the spline is not causal).
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/model/model.hpp"
#include "framework/model/signal_stream.hpp"
#include "framework/model/streaming_model.hpp"

namespace hystbench {

// The keys model_stream() reads, for the caller's key check.
const std::vector<std::string>& model_stream_keys();

// The model a spec names, before it becomes a stream.
struct ResolvedModel {
  Model model;
  Eigen::VectorXd x;  // normalised parameters
  SignalScales scales;
  std::string description;
  InputHold hold = InputHold::Linear;
};

// Throws InputError naming `where` and the bad key.
ResolvedModel resolve_model(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                            const std::string& where);
// Its stream in normalised units; throws InputError when its parameters are invalid.
std::unique_ptr<StreamingModel> streaming_model(const ResolvedModel& model, double sample_time,
                                                const std::string& where);

struct ModelStream {
  std::unique_ptr<SignalStream> stream;
  std::string description;  // "fit.json: hysteresis,asymmetry,msd,arx"
};

// Throws InputError naming `where` and the bad key. Relative paths are
// found like data files (resolve_data_path).
ModelStream model_stream(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                         double sample_time, const std::string& where);

}  // namespace hystbench
