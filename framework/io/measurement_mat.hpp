#pragma once
// Measurements in MAT files: the vectors the column map names (t, u, y and
// an optional segment), checked as a CSV's columns are. read_measurement and
// write_measurement come here for a MAT file (framework/io/mat_file.hpp).
#include <filesystem>

#include "framework/io/measurement.hpp"

namespace hystbench {

Measurement read_measurement_mat(const std::filesystem::path& path, const ColumnMap& columns);

// t, u, y (and segment) as column vectors of a v7 MAT file.
void write_measurement_mat(const std::filesystem::path& path, const Measurement& m);

}  // namespace hystbench
