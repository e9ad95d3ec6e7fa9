#pragma once
// Synthetic measurements: a model's response to an excitation plus seeded
// Gaussian noise, with the "truth" record that makes the noise floor known.
// Each kind of model (the seed model, a discovery model) fills one.
#include "framework/core/eigen.hpp"
#include <cstdint>
#include <nlohmann/json.hpp>

#include "framework/io/measurement.hpp"

namespace hystbench {

struct SyntheticData {
  Measurement data;
  nlohmann::json truth;  // parameters, noise, noise-floor SSE, excitation
};

// Adds seeded Gaussian noise of sd relative·RMS(y) to y; returns the sd.
double add_relative_noise(Eigen::VectorXd& y, double relative, std::uint64_t seed);

}  // namespace hystbench
