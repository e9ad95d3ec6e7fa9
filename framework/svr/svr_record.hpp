#pragma once
// A stretch of a measurement that the SVR model trains or is tested on: a
// CSV, or one segment of it (seed 002 trains stage 1 on a 1 Hz record and
// stage 2 on a frequency scan; one simulated file can hold both).
#include <filesystem>
#include <string>

#include "framework/io/measurement.hpp"

namespace hystbench {

struct SvrRecord {
  std::string name;  // "train.csv", or "train.csv [train 1 Hz]" for a segment
  Measurement data;  // only the chosen samples
};

// Reads `file` (resolved as experiment files are, data_path.hpp) and keeps
// the samples labelled `segment` (all when empty). Throws InputError naming
// `where` when the segment is absent (listing those present) or broken into
// several stretches.
SvrRecord read_svr_record(const std::string& file, const std::string& segment, const ColumnMap& columns,
                          const std::filesystem::path& base_dir, const std::string& where);

// The samples [begin, end) of `m`, its labels included.
Measurement slice(const Measurement& m, Eigen::Index begin, Eigen::Index end);

}  // namespace hystbench
