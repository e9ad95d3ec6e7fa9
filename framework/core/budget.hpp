#pragma once
// What a trial may spend, and why it stopped.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace hystbench {

// Any combination of limits; the first one reached stops the trial.
struct Budget {
  std::optional<long> evaluations;  // fitness evaluations, initialisation included
  std::optional<long> iterations;   // generations after initialisation
  std::optional<double> seconds;    // wall time (makes results machine-dependent)
  std::optional<double> target;     // stop once best fitness <= target

  // Reads {"evaluations": .., "iterations": .., "seconds": .., "target": ..}.
  // `where` names the JSON location for messages. Throws InputError.
  static Budget from_json(const nlohmann::json& j, const std::string& where);
  nlohmann::json to_json() const;
};

// Why a trial ended. Round-trips through its string form, as in JSON files.
enum class StopReason {
  Running,      // not stopped yet
  Evaluations,  // evaluation budget used up
  Iterations,   // iteration budget used up
  Seconds,      // wall-time budget used up
  Target,       // target fitness reached
  Converged,    // the optimizer ended by itself
  Failed,       // the optimizer threw; see the trial's message
};

std::string to_string(StopReason reason);
StopReason stop_reason_from_string(const std::string& text);

}  // namespace hystbench
