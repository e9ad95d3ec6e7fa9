#pragma once
// The files `hystbench track` writes (docs/tracking.md#outputs):
// controller.json (the nominal model, the weights, the generalized plant's
// matrices, γ, the full and reduced controllers with their poles, zeros and
// checks, what the seed's printed numbers give), tracking.json (one row per
// reference and controller) and the tables in the layout of seed 002's
// Table 2.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/tracking/tracking_run.hpp"

namespace hystbench {

nlohmann::json controller_json(const TrackingExperiment& x, const TrackingResults& r);
nlohmann::json tracking_json(const TrackingExperiment& x, const TrackingResults& r, int threads);

// controller.json, tracking.json, table.md, table.tex, table.csv.
std::vector<std::filesystem::path> write_tracking_report(const std::filesystem::path& dir,
                                                         const TrackingExperiment& x, const TrackingResults& r,
                                                         int threads);

}  // namespace hystbench
