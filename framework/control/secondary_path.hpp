#pragma once
// A secondary-path estimate S_hat the controller filters its reference with
// (docs/control.md#secondary-path), as a "secondary" object names it:
//
//   {"type": "linear_true"}   the plant's exact linear control path (no actuator
//                             model): isolates the step rule
//   {"type": "model", ...}    an identified model (actuator_model.hpp keys), e.g.
//                             the fit.json of `hystbench fit` / `discover`, run on
//                             the reference sample by sample as seed 000 did; with
//                             "then_plant": true it is an actuator model followed
//                             by the plant's linear control path
//   {"type": "fir_lms",       an FIR identified offline by normalised LMS from
//    "taps": 512,             white noise through the true control path, with
//    "seconds": 60,           the loop's sensor noise
//    "excitation": 1, "step": 0.1}
//
// Its error at the disturbance (phase of S_hat / S, |phase| > 90 degrees makes
// FxLMS diverge, and the gain ratio) is measured once, when it is built.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/control/control_loop.hpp"
#include "framework/control/plant.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

struct EstimateError {
  double phase_deg = 0.0;   // arg(S_hat / S) at the disturbance
  double gain_ratio = 1.0;  // |S_hat / S| there
};

struct SecondaryPath {
  std::unique_ptr<SignalStream> stream;
  std::string description;
  EstimateError error;
};

// Where an estimate is built: the plant, the true control path (actuator
// included), the loop and the noise of an identification run.
struct EstimateContext {
  const Plant& plant;
  const SignalStream& true_path;
  const LoopSettings& loop;
  std::uint64_t identification_seed;
  std::filesystem::path base_dir;
};

// Throws InputError naming `where` and the bad key.
SecondaryPath secondary_path(const nlohmann::json& spec, const EstimateContext& context,
                             const std::string& where);

}  // namespace hystbench
