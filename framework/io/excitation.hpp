#pragma once
// Input signals for synthetic experiments, built from a JSON spec:
//
//   {"sample_rate": 1000,
//    "segments": [
//      {"type": "sine", "frequency": 5, "amplitude": 625, "offset": 375,
//       "phase_deg": -36.87, "duration": 2, "label": "sine_5Hz"},
//      {"type": "sweep", "f0": 1, "f1": 50, "duration": 10, "amplitude": 500},
//      {"type": "multisine", "frequencies": [10, 30, 50], "amplitude": 75,
//       "offset": 75, "phase_deg": -90, "duration": 0.5},
//      {"type": "steps", "levels": [0, 500, 1000], "hold": 2, "ramp": 0.05}]}
//
// Segments follow each other; each has its own local time starting at 0.
// "label" is optional (default e.g. "sine_5Hz", "sweep_1-50Hz",
// "multisine_10/30/50Hz", "steps"). A multisine is the mean of its sines
// times `amplitude`, so it never leaves offset ± amplitude.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hystbench {

struct Excitation {
  double sample_rate = 0.0;
  Eigen::VectorXd t;
  Eigen::VectorXd u;
  std::vector<std::string> segment;
};

// Throws InputError naming the bad key, e.g. "excitation.segments[2].frequency".
Excitation make_excitation(const nlohmann::json& spec);

}  // namespace hystbench
