#include "framework/io/measurement_mat.hpp"

#include <cmath>

#include "framework/core/text.hpp"
#include "framework/io/mat_file.hpp"
#include "framework/io/measurement_csv_lines.hpp"
#include "framework/io/measurement_csv_rows.hpp"

namespace hystbench {
namespace {

using measurement_csv::fail;

// As in a CSV: squares of larger values, summed over a record, overflow.
constexpr double kLargestValue = 1e150;

std::vector<double> checked(const Eigen::VectorXd& v, const std::string& file,
                            const std::string& column) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const std::size_t sample = std::size_t(i) + 1;
    const std::string at = "variable '" + column + "': " + number_text(v[i]);
    if (!std::isfinite(v[i]))
      fail({file, sample, "sample"},
           at + " is not a finite number (NaN and Inf are not allowed); fix or remove the sample");
    if (std::abs(v[i]) > kLargestValue)
      fail({file, sample, "sample"}, at + " is too large: squared errors of values beyond 1e150 "
                                          "overflow; rescale the variable (other units)");
  }
  return {v.data(), v.data() + v.size()};
}

void check_length(std::size_t n, std::size_t expected, const std::string& file,
                  const std::string& name, const std::string& time_name) {
  if (n != expected)
    throw InputError(file + ": '" + name + "' has " + std::to_string(n) + " samples but '" +
                     time_name + "' has " + std::to_string(expected) +
                     "; t, u, y and segment must have the same length");
}

}  // namespace

Measurement read_measurement_mat(const std::filesystem::path& path, const ColumnMap& columns) {
  const MatReader mat(path);
  const std::string& file = mat.name();
  measurement_csv::Rows rows;
  rows.unit = "sample";
  rows.t = checked(mat.vector(columns.t, "t", &rows.time_digits), file, columns.t);
  rows.u = checked(mat.vector(columns.u, "u"), file, columns.u);
  check_length(rows.u.size(), rows.t.size(), file, columns.u, columns.t);
  rows.y = checked(mat.vector(columns.y, "y"), file, columns.y);
  check_length(rows.y.size(), rows.t.size(), file, columns.y, columns.t);
  if (auto labels = mat.labels(columns.segment)) {
    check_length(labels->size(), rows.t.size(), file, columns.segment, columns.t);
    rows.segment = std::move(*labels);
  }
  for (std::size_t i = 0; i < rows.t.size(); ++i) rows.line.push_back(i + 1);
  measurement_csv::Header header;
  header.names = {columns.t, columns.u, columns.y};
  return measurement_csv::to_measurement(rows, header, file);
}

void write_measurement_mat(const std::filesystem::path& path, const Measurement& m) {
  std::vector<std::pair<std::string, std::vector<std::string>>> texts;
  if (!m.segment.empty()) texts.emplace_back("segment", m.segment);
  write_mat_file(path, {{"t", m.t}, {"u", m.u}, {"y", m.y}}, texts);
}

}  // namespace hystbench
