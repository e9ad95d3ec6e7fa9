#pragma once
// An experiment file: which problem, which algorithms, what budget, how many
// seeded trials. Everything is validated on load, before any output exists.
//
//   {"name": "demo",
//    "problem": {"type": "hammerstein", "data": "problems/hammerstein/data/default.csv"},
//    "budget": {"evaluations": 5000},
//    "trials": 10, "seed": 1,
//    "algorithms": [{"name": "de", "label": "DE", "params": {"np": 50}}]}
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/core/budget.hpp"

namespace hystbench {

// "polish": {"algorithm": "LN_BOBYQA", "fraction": 0.2, "repeat": false}:
// the last fraction of the evaluation budget goes to a local search from the
// best point, in the same budget and trace. The local search is an NLopt
// method, or "levenberg_marquardt" on least-squares problems. With
// "repeat", a local search that converges before the budget is spent is
// followed by a fresh run of the optimizer on (1 - fraction) of what
// remains and another polish, until the budget or the target ends the trial.
struct PolishSpec {
  static constexpr const char* kLevenbergMarquardt = "levenberg_marquardt";
  std::string algorithm = "LN_BOBYQA";
  double fraction = 0.2;
  bool repeat = false;
};

struct AlgorithmSpec {
  std::string name;       // plugin name
  std::string label;      // unique within the experiment; defaults to name
  nlohmann::json params;  // validated, defaults filled in
  std::optional<PolishSpec> polish;
};

struct Experiment {
  std::string name;
  std::string description;
  // "default", or "seed": the results table with the columns of MEDE's
  // Table 1, Best beside f_min although they coincide (framework/report/tables.hpp).
  std::string table_layout = "default";
  nlohmann::json problem;  // the "problem" object, checked against its registry entry
  Budget budget;
  long trials = 0;
  std::uint64_t seed = 0;
  std::vector<AlgorithmSpec> algorithms;
  std::filesystem::path base_dir;  // folder of the experiment file

  // Throws InputError whose message starts with the file name.
  static Experiment load(const std::filesystem::path& file);
  // The same from the file's text; `where` stands for the file name in
  // messages. base_dir stays empty.
  static Experiment parse(std::istream& in, const std::string& where);
  // `where` prefixes messages (the file name, or "experiment").
  static Experiment from_json(const nlohmann::json& j, const std::string& where);
  nlohmann::json to_json() const;
};

}  // namespace hystbench
