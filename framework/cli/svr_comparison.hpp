#pragma once
// An SVR model (svr_model.json from `hystbench svr`) as the model under
// test of `compare` and `diagnose`: simulated in free run from the record's
// first measured samples, then scored, broken down and tested like a
// catalog fit (metrics.json, report.md and figures in the output folder).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/cli/model_options.hpp"
#include "framework/discovery/comparison.hpp"

namespace hystbench::cli {

// `file` is the model file's JSON, `path` its name for messages. The whole
// record is scored unless the command was given --holdout. Prints the
// headline errors; returns the comparison.
Comparison compare_svr_model(const nlohmann::json& file, const std::string& path, const DataOptions& data,
                             const OutputOptions& output, const CLI::App& cmd,
                             const std::string& mat = "");

}  // namespace hystbench::cli
