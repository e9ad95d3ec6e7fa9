#include "framework/cli/simulation_recipe.hpp"

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/json_file.hpp"
#include "problems/hammerstein/hammerstein_synthetic_data.hpp"

namespace hystbench::cli {
namespace {

SyntheticData make_data(const SimulationRecipe& r, const std::filesystem::path& root) {
  const auto values = read_json_file(root / r.params, "parameter file");
  const auto excitation = read_json_file(root / r.excitation, "excitation file");
  if (!r.model.empty()) {
    Model model = Model::parse(r.model);
    model.set_substeps(r.substeps);
    model.set_input_hold(r.input_hold);
    return make_model_synthetic_data(model, values, excitation, r.noise, r.seed, r.params, r.resolution);
  }
  if (r.resolution > 0.0)
    throw InputError("--resolution needs --model: give the effects to simulate, e.g. --model hysteresis,msd");
  const auto params = read_hammerstein_params(values, r.params);
  try {
    return make_synthetic_data(params, bouc_wen_form_from_string(r.form), excitation, r.noise, r.seed);
  } catch (const InputError& e) {
    throw InputError(r.excitation + ": " + e.what());
  }
}

}  // namespace

std::string simulate_command_line(const SimulationRecipe& r) {
  std::string c = "hystbench simulate";
  if (!r.model.empty()) c += " --model " + r.model;
  if (r.substeps) c += " --substeps " + std::to_string(r.substeps);
  if (r.input_hold != InputHold::Spline) c += " --input-hold " + to_string(r.input_hold);
  c += " --params " + r.params + " --excitation " + r.excitation + " --noise " + number_text(r.noise) +
       " --seed " + std::to_string(r.seed);
  if (r.resolution > 0.0) c += " --resolution " + number_text(r.resolution);
  if (!r.input_unit.empty()) c += " --input-unit " + r.input_unit;
  if (!r.output_unit.empty()) c += " --output-unit " + r.output_unit;
  return c + " --out " + r.out;
}

SimulatedRecord write_simulated_record(const SimulationRecipe& r, const std::filesystem::path& root) {
  SyntheticData s = make_data(r, root);
  std::filesystem::path truth_path = root / r.out;
  truth_path.replace_extension(".truth.json");
  const std::string command = simulate_command_line(r);
  s.truth["generated_by"] = command;
  s.truth["units"] = {{"t", "s"}, {"u", r.input_unit}, {"y", r.output_unit}};
  const std::string kind = r.model.empty() ? "Hammerstein (MFC-like)" : "model " + r.model;
  write_measurement(root / r.out, s.data,
                    {"Synthetic " + kind + " data; true parameters and noise floor in " +
                         truth_path.filename().string(),
                     "Regenerate: " + command});
  write_file_atomic(truth_path, s.truth.dump(2) + "\n");
  return {static_cast<std::size_t>(s.data.size()), s.truth["noise_floor_sse"].get<double>(), truth_path};
}

}  // namespace hystbench::cli
