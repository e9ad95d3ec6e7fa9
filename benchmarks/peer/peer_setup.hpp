#pragma once
// What every part of the comparison shares: the problem, its noise floor,
// and the trial protocol.
#include <cstdint>
#include <nlohmann/json.hpp>

#include "framework/core/problem.hpp"

namespace hystbench::peer {

struct PeerSetup {
  const Problem* problem = nullptr;
  nlohmann::json problem_spec;  // the experiment-file "problem" object it was built from
  double noise_floor = 1.0;     // SSE of the true parameters
  long budget = 20000;          // evaluations per trial in the equal-budget part
  long trials = 5;
  std::uint64_t seed = 1;
};

}  // namespace hystbench::peer
