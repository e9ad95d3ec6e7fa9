#include "framework/cli/comparison_output.hpp"

#include <iostream>

#include "framework/cli/fit_summary.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/io/mat_file.hpp"

namespace hystbench::cli {
namespace {

void write_comparison_mat(const std::string& mat, const ComparisonInput& input) {
  std::vector<std::pair<std::string, std::vector<std::string>>> labels;
  if (!input.segment.empty()) labels.emplace_back("segment", input.segment);
  write_mat_file(mat, {{"t", input.t}, {"u", input.u}, {"y", input.y}, {"y_model", input.y_model},
                       {"residual", input.y - input.y_model}}, labels);
}

}  // namespace

Comparison write_and_print_comparison(const std::filesystem::path& dir, const DataSource& source,
                                      const ModelData& data, Eigen::VectorXd y_model, const std::string& model_text,
                                      const std::string& model_line, const std::string& mat,
                                      ComparisonInput::Record record) {
  auto input = comparison_input(data, std::move(y_model), source.u_unit, source.y_unit);
  input.record = record;
  const Comparison metrics = compare_signals(input);
  // First: a MAT file that cannot be written leaves nothing else behind.
  if (!mat.empty()) write_comparison_mat(mat, input);
  const auto files = write_comparison(dir, input, metrics, "Model " + model_text + " against " + source.file_name(),
                                      model_text);
  std::cout << "model " << model_line << "\n";
  print_comparison_headline(metrics, source.y_unit);
  std::cout << "wrote " << files.size() << " files in " << dir.string() << " (see report.md)\n";
  if (!mat.empty()) std::cout << "wrote " << mat << " (t, u, y, y_model, residual)\n";
  return metrics;
}

}  // namespace hystbench::cli
