#include "framework/discovery/model_synthetic_data.hpp"

#include "framework/core/error.hpp"
#include "framework/io/excitation.hpp"

namespace hystbench {

SyntheticData make_model_synthetic_data(const Model& model, const nlohmann::json& values,
                                        const nlohmann::json& excitation_spec,
                                        double noise_relative, std::uint64_t seed,
                                        const std::string& where, double resolution) {
  const bool nested = values.is_object() && values.contains("parameters");
  const nlohmann::json& physical = nested ? values.at("parameters") : values;
  const SignalScales unit_scales;  // physical units throughout
  const Eigen::VectorXd x = model.from_physical(physical, unit_scales, where);
  const Excitation ex = make_excitation(excitation_spec);
  Measurement m{ex.t, ex.u, ex.u, ex.segment, 1.0 / ex.sample_rate, "", "", ""};
  Eigen::VectorXd clean;
  if (!model.simulate(x, ModelData(m, unit_scales), clean))
    throw InputError(where + ": model " + model.text() + " diverges on this excitation");
  m.y = clean;
  const double sd = add_relative_noise(m.y, noise_relative, seed);
  if (resolution > 0.0) m.y = (m.y / resolution).array().round() * resolution;
  // Rounding adds a uniform error of variance resolution²/12 per sample.
  const double variance = sd * sd + resolution * resolution / 12.0;
  nlohmann::json truth = {
      {"model", model.text()},
      {"parameters", model.physical_values(x, unit_scales)},
      {"substeps", model.substeps()},
      {"noise", {{"relative_to_output_rms", noise_relative}, {"sd", sd}, {"seed", seed},
                 {"resolution", resolution}}},
      {"samples", m.size()},
      {"sample_time", m.sample_time},
      {"noise_floor_sse", (m.y - clean).squaredNorm()},
      {"expected_noise_sse", double(m.size()) * variance},
      {"excitation", excitation_spec}};
  if (model.input_hold() != InputHold::Spline) truth["input_hold"] = to_string(model.input_hold());
  return {std::move(m), std::move(truth)};
}

}  // namespace hystbench
