#pragma once
// Synthetic measurements from a discovery model with known physical
// parameters: how data with a hidden effect are made, and how the tests and
// benchmarks know the noise level a perfect discovery would reach.
#include <nlohmann/json.hpp>

#include "framework/model/model.hpp"
#include "framework/io/synthetic_data.hpp"

namespace hystbench {

// `values`: physical parameter values {"gain": .., "hysteresis.A": .., ...}
// (or {"parameters": {...}}), every parameter of `model` required. The truth
// records the model, the values, the noise sd and the noise-floor SSE.
// `resolution` > 0 rounds the noisy output to its multiples, as a sensor of
// that resolution reads it. Throws InputError when a value is missing or the
// model diverges.
SyntheticData make_model_synthetic_data(const Model& model, const nlohmann::json& values,
                                        const nlohmann::json& excitation_spec,
                                        double noise_relative, std::uint64_t seed,
                                        const std::string& where, double resolution = 0.0);

}  // namespace hystbench
