#pragma once
// What every table caption and figure title needs to say about a run.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace hystbench {

struct ReportContext {
  std::string experiment;          // experiment name
  std::string problem;             // Problem::name()
  std::string budget;              // human-readable, e.g. "5000 evaluations"
  long trials = 0;                 // trials per algorithm
  std::uint64_t seed = 0;
  std::optional<double> noise_floor;  // SSE of the true parameters, when known
  std::string input_unit;          // of u, e.g. "V"; empty when unknown
  std::string output_unit;         // of y, e.g. "µm"
  std::string fitness;             // what the fitness is, e.g. "SSE"; empty when unnamed
  bool seed_table_layout = false;  // the results table as MEDE's Table 1 (Experiment::table_layout)
  // "Best-so-far fitness (SSE)", or without the parentheses when unnamed.
  std::string fitness_axis(const std::string& what) const {
    return what + (fitness.empty() ? "" : " (" + fitness + ")");
  }
};

}  // namespace hystbench
