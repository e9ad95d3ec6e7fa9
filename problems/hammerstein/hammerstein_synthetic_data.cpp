#include "problems/hammerstein/hammerstein_synthetic_data.hpp"

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/io/excitation.hpp"

namespace hystbench {

HammersteinParams read_hammerstein_params(const nlohmann::json& j, const std::string& where) {
  const bool nested = j.is_object() && j.contains("parameters");
  const nlohmann::json& values = nested ? j.at("parameters") : j;
  const std::string at = nested ? where + ".parameters" : where;
  const auto& names = HammersteinParams::names();
  require_known_keys(values, {names.begin(), names.end()}, at);
  Eigen::VectorXd x(HammersteinParams::kCount);
  for (int i = 0; i < HammersteinParams::kCount; ++i) {
    if (!values.contains(names[i]) || !values[names[i]].is_number())
      throw InputError(at + "." + names[i] + ": missing or not a number (all 13 parameters are required)");
    x[i] = values[names[i]].get<double>();
  }
  return HammersteinParams::from_vector(x);
}

SyntheticData make_synthetic_data(const HammersteinParams& params, BoucWenForm form,
                                  const nlohmann::json& excitation_spec, double noise_relative,
                                  std::uint64_t seed) {
  const Excitation ex = make_excitation(excitation_spec);
  const double Ts = 1.0 / ex.sample_rate;
  const Eigen::VectorXd clean = simulate_hammerstein(params, ex.u, Ts, form);
  if (!clean.allFinite() || !linear_blocks_stable(params, Ts))
    throw InputError("parameters: the model diverges on this excitation (unstable block?)");

  Measurement m{ex.t, ex.u, clean, ex.segment, Ts, "", "", ""};
  const double sd = add_relative_noise(m.y, noise_relative, seed);

  nlohmann::json p = nlohmann::json::object();
  const Eigen::VectorXd x = params.to_vector();
  for (int i = 0; i < HammersteinParams::kCount; ++i) p[HammersteinParams::names()[i]] = x[i];
  const nlohmann::json truth = {
      {"model", "hammerstein"},
      {"bouc_wen_form", to_string(form)},
      {"parameters", p},
      {"noise", {{"relative_to_output_rms", noise_relative}, {"sd", sd}, {"seed", seed}}},
      {"samples", m.size()},
      {"sample_time", Ts},
      {"noise_floor_sse", hammerstein_sse(params, m.u, m.y, Ts, form)},
      {"expected_noise_sse", double(m.size()) * sd * sd},
      {"excitation", excitation_spec}};
  return {std::move(m), truth};
}

}  // namespace hystbench
