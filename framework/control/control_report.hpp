#pragma once
// control.json (docs/control.md#outputs): the experiment as read, what the
// setup derived (plant details, estimate error, noise level), and an entry
// per controller label with its metrics' mean and std over the trials.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/control/control_run.hpp"

namespace hystbench {

nlohmann::json control_json(const ControlExperiment& x, const ControlSetup& setup,
                            const ControlResults& results, int threads);

}  // namespace hystbench
