#pragma once
// The candidates figure of `hystbench diagnose`: per candidate effect the
// estimation and the held-out RMSE after adding it, each bar marked with the
// current model's RMSE of the same kind, and the noise floor.
#include <filesystem>
#include <string>

#include "framework/discovery/diagnosis.hpp"

namespace hystbench {

// Writes diagnosis_candidates.gp and .csv (effect,rmse_after,
// heldout_rmse_after) in `dir`; returns the script path. Without held-out
// data only the estimation bars are drawn.
std::filesystem::path write_candidates_figure(const std::filesystem::path& dir, const Diagnosis& d,
                                              const std::string& y_unit);

}  // namespace hystbench
