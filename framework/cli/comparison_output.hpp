#pragma once
// What `compare` (and `diagnose` of an SVR model) write and print for a
// model output set against the data: metrics.json, report.md and figures in
// `dir`, then "model <line>", the headline errors and the files written;
// with `mat`, also t, u, y, y_model and the residual as that MAT file.
// `record`: what the data are to the model (comparison.hpp).
#include "framework/core/eigen.hpp"
#include <filesystem>
#include <string>

#include "framework/discovery/comparison.hpp"
#include "framework/discovery/data_source.hpp"

namespace hystbench::cli {

Comparison write_and_print_comparison(const std::filesystem::path& dir, const DataSource& source,
                                      const ModelData& data, Eigen::VectorXd y_model, const std::string& model_text,
                                      const std::string& model_line, const std::string& mat = "",
                                      ComparisonInput::Record record = ComparisonInput::Record::Fitted);

}  // namespace hystbench::cli
