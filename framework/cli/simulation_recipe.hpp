#pragma once
// What `hystbench simulate` writes, as one value: the command's options. An
// experiment's "records" file lists recipes too, so that a bundled
// experiment makes the records it reads, the same bits as the command
// (framework/cli/experiment_records.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

#include "framework/model/input_hold.hpp"

namespace hystbench::cli {

// The largest values simulate takes, on its command line and in a records
// file alike.
inline constexpr double kMaxRecipeNoise = 10.0;       // a fraction of the output RMS
inline constexpr double kMaxRecipeResolution = 1e6;  // output units
inline constexpr int kMaxRecipeSubsteps = 1000;

// Whether `form` names a Bouc-Wen form simulate knows.
inline bool known_form(const std::string& form) { return form == "increment" || form == "paper"; }

struct SimulationRecipe {
  std::string params, excitation, out, form = "increment", input_unit, output_unit, model;
  InputHold input_hold = InputHold::Spline;
  int substeps = 0;
  double noise = 0.01, resolution = 0.0;
  std::uint64_t seed = 1;
};

// The command line that remakes the record; it is written into the record.
std::string simulate_command_line(const SimulationRecipe& r);

// Simulates the record and writes `out` with its truth file beside it. The
// recipe's relative file names are read and written under `root`; the record
// names them as given, so its bits do not depend on where it was made.
// Throws InputError.
struct SimulatedRecord {
  std::size_t samples = 0;
  double noise_floor_sse = 0.0;
  std::filesystem::path truth;  // the truth file written beside the record
};
SimulatedRecord write_simulated_record(const SimulationRecipe& r, const std::filesystem::path& root = {});

}  // namespace hystbench::cli
