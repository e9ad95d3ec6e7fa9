#pragma once
// What one finished trial leaves behind: one line of trials.jsonl.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/core/budget.hpp"
#include "framework/core/evaluation_context.hpp"

namespace hystbench {

struct TrialResult {
  std::string label;           // algorithm label from the experiment
  int algorithm_index = 0;     // position in the experiment's algorithm list
  long trial = 0;              // trial index, 0-based
  std::uint64_t seed = 0;      // derived trial seed
  double best = 0.0;           // final best-so-far fitness (+inf if none finite)
  long evaluations = 0;
  long iterations = 0;
  StopReason stop = StopReason::Running;
  std::vector<double> best_x;
  std::vector<TracePoint> trace;  // best-so-far improvements
  double wall_seconds = 0.0;
  std::string message;         // why it failed, when stop == Failed

  bool failed() const { return stop == StopReason::Failed; }
  nlohmann::json to_json() const;
  static TrialResult from_json(const nlohmann::json& j);
};

}  // namespace hystbench
