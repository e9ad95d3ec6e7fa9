#pragma once
// The rows of a measurement CSV as read, between its reader, which parses
// them, and the checks that turn them into a Measurement.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "framework/io/measurement.hpp"

namespace hystbench::measurement_csv {

// The header row: the column names, where t, u, y and segment are, and the
// field delimiter.
struct Header {
  std::vector<std::string> names;
  std::size_t line = 0;
  std::size_t t = 0, u = 0, y = 0;
  std::optional<std::size_t> segment;
  char delimiter = ',';
};

// The data rows column by column, with the line each came from.
struct Rows {
  std::vector<double> t, u, y;
  std::vector<std::string> segment;
  std::vector<std::size_t> line;
  const char* unit = "line";  // what `line` counts: "sample" in a MAT file
  int time_digits = 0;
};

// Checks that the time strictly increases and is evenly sampled, infers the
// sample time and moves the rows into a Measurement. InputError naming file,
// line and column otherwise, or when there are fewer than two samples.
Measurement to_measurement(Rows& rows, const Header& h, const std::string& file);

}  // namespace hystbench::measurement_csv
