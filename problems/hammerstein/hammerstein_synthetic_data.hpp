#pragma once
// Synthetic measurements from known parameters of the 13-parameter seed
// model (framework/io/synthetic_data.hpp says what they hold).
#include <nlohmann/json.hpp>

#include "framework/io/synthetic_data.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"

namespace hystbench {

// Reads {"alpha": .., ..., "d": ..} or a truth file {"parameters": {...}}.
// Every one of the 13 names is required. Throws InputError naming the key.
HammersteinParams read_hammerstein_params(const nlohmann::json& j, const std::string& where);

// noise_relative: noise standard deviation as a fraction of the RMS of the
// noise-free output. The truth's "noise_floor_sse" is the fitness of the true
// parameters on the noisy data: no fit can be expected to do better.
SyntheticData make_synthetic_data(const HammersteinParams& params, BoucWenForm form,
                                  const nlohmann::json& excitation_spec, double noise_relative,
                                  std::uint64_t seed);

}  // namespace hystbench
