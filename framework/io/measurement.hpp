#pragma once
// Measurement records: time t, input u, output y, optional segment label.
#include "framework/core/eigen.hpp"
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "framework/io/column_map.hpp"

namespace hystbench {

struct Measurement {
  Eigen::VectorXd t;
  Eigen::VectorXd u;
  Eigen::VectorXd y;
  std::vector<std::string> segment;  // one label per sample, or empty
  double sample_time = 0.0;          // inferred from t, in s
  std::string source;                // file it was read from
  std::string u_unit, y_unit;        // from the header ("voltage [V]"), or empty

  Eigen::Index size() const { return t.size(); }
};

// Reads a measurement CSV (docs/formats.md#measurement-csv). InputError naming
// file, line and column for: missing or empty file, missing or duplicate
// column, a value not a finite number or beyond 1e150, ragged row, time not
// increasing or not evenly sampled, fewer than two samples. Accepts a UTF-8
// BOM, CRLF line ends, quoted fields, extra columns, '#' and '%' comment lines, ',',
// ';' or tab between fields (decimal commas with the last two), common
// column names with units (header_names.hpp); a time in ms, µs, min or h is
// read in seconds.
Measurement read_measurement(const std::filesystem::path& path, const ColumnMap& columns = {});

// The same reading, from the text of a file; `source` stands for the file
// name in messages and in Measurement::source.
Measurement parse_measurement(std::string_view text, const std::string& source,
                              const ColumnMap& columns = {});

// Writes t,u,y[,segment] with 17 significant digits; `comments` become '#'
// lines at the top.
void write_measurement(const std::filesystem::path& path, const Measurement& m,
                       const std::vector<std::string>& comments = {});

}  // namespace hystbench
