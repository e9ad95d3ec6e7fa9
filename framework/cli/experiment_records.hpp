#pragma once
// The records a bundled experiment reads, made on demand. An experiment may
// name a records file:
//
//   "records": "benchmarks/experiments/svr_piezo/records.json"
//
//   {"made_by": "benchmarks/svr_piezo.sh",
//    "simulate": [{"out": "results/svr/data/train.csv", "model": "...", "params": "...",
//                  "excitation": "...", "noise": 0.005, "seed": 202, ...}, ...]}
//
// Each entry of "simulate" holds the options of `hystbench simulate` (keys
// without the dashes, '_' for '-'). A record whose file is missing is
// simulated where the experiment looks for it, the same bits as that
// command, so the experiment runs from a clean checkout. "made_by" names
// the script that makes the experiment's other files; a file-not-found
// error names it.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "framework/core/error.hpp"

namespace hystbench::cli {

// Validates the experiment's records file, then simulates every record that
// is missing, saying so on `log`. Returns "made_by" ("" when none). Throws
// InputError before anything is written.
std::string make_missing_records(const std::filesystem::path& experiment, std::ostream& log);

// Makes the missing records, then loads the experiment.
template <class Experiment>
Experiment load_with_records(const std::filesystem::path& experiment, std::ostream& log) {
  const std::string made_by = make_missing_records(experiment, log);
  try {
    return Experiment::load(experiment);
  } catch (const MissingFileError& e) {
    if (made_by.empty()) throw;
    throw MissingFileError(std::string(e.what()) + "; " + made_by + " makes the files this experiment reads");
  }
}

}  // namespace hystbench::cli
