#pragma once
// The tables of a control experiment (docs/control.md#outputs), laid out
// like seed 000's error-metric and efficiency tables: one row per
// controller, RMSE, MAE and efficiency on the measured error, then the same
// with attenuation and convergence time on the true (noise-free) error, and
// whether the loop diverged. table.{md,tex,csv} holds the compared
// controllers, step_sweep.{md,tex,csv} the fixed-step sweep.
#include <filesystem>
#include <vector>

#include "framework/control/control_run.hpp"

namespace hystbench {

// Writes the tables into `dir`; returns the files written.
std::vector<std::filesystem::path> write_control_tables(const std::filesystem::path& dir,
                                                        const ControlExperiment& x,
                                                        const ControlResults& results);

}  // namespace hystbench
