#pragma once
// The files `hystbench svr` writes (docs/svr.md#outputs): svr_model.json
// (the fitted model, loadable), aic.csv (the ARX grid, with a stage 2), svr.json (the
// hyperparameters, the orders, one row per test signal) and the tables in
// the layout of seed 002's Table 1: signal, ARMSE, RE, for the SVR model
// and the grey-box fit side by side.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/svr/svr_run.hpp"

namespace hystbench {

nlohmann::json svr_json(const SvrExperiment& x, const SvrResults& r, int threads);

// svr_model.json, aic.csv, svr.json, table.md, table.tex, table.csv.
std::vector<std::filesystem::path> write_svr_report(const std::filesystem::path& dir, const SvrExperiment& x,
                                                    const SvrResults& r, int threads);

}  // namespace hystbench
