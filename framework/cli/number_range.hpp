#pragma once
// Range checks of numeric options that a person can read. CLI11's Range
// prints an open bound as a 309-digit number and says nothing of what to
// give; these name the value and say what is allowed instead:
//   --evaluations: -5 is not allowed; give a positive number of evaluations (0 = default)
#include <CLI/CLI.hpp>
#include <limits>
#include <string>

namespace hystbench::cli {

// An open end of a range.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Accepts numbers from `lowest` to `highest`, both included. Refuses any
// other value with "VALUE is not allowed; HINT" (CLI11 puts the option's
// name in front); `hint` says what to give, in words.
CLI::Validator number_range(double lowest, double highest, const std::string& hint);

// The hint of --substeps, an option of fit, diagnose, discover and simulate.
constexpr const char* kSubstepsHint = "give 1 to 1000 sub-steps per sample (0 = each effect's default)";

}  // namespace hystbench::cli
