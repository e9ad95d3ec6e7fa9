#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "framework/cli/commands.hpp"
#include "framework/cli/input_hold_option.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/text.hpp"
#include "framework/core/error.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/json_file.hpp"
#include "problems/hammerstein/hammerstein_synthetic_data.hpp"

namespace hystbench::cli {
namespace {

struct SimulateOptions {
  std::string params, excitation, out, form = "increment", input_unit, output_unit, model;
  InputHold input_hold = InputHold::Spline;
  int substeps = 0;
  double noise = 0.01, resolution = 0.0;
  std::uint64_t seed = 1;
};

SyntheticData make_data(const SimulateOptions& o) {
  const auto values = read_json_file(o.params, "parameter file");
  const auto excitation = read_json_file(o.excitation, "excitation file");
  if (!o.model.empty()) {
    Model model = Model::parse(o.model);
    model.set_substeps(o.substeps);
    model.set_input_hold(o.input_hold);
    return make_model_synthetic_data(model, values, excitation, o.noise, o.seed, o.params,
                                     o.resolution);
  }
  if (o.resolution > 0.0)
    throw InputError("--resolution needs --model: give the effects to simulate, e.g. --model hysteresis,msd");
  const auto params = read_hammerstein_params(values, o.params);
  try {
    return make_synthetic_data(params, bouc_wen_form_from_string(o.form), excitation, o.noise, o.seed);
  } catch (const InputError& e) {
    throw InputError(o.excitation + ": " + e.what());
  }
}

void simulate(const SimulateOptions& o) {
  SyntheticData s = make_data(o);
  std::filesystem::path truth_path(o.out);
  truth_path.replace_extension(".truth.json");
  const std::string command = "hystbench simulate" +
                              (o.model.empty() ? "" : " --model " + o.model) +
                              (o.substeps ? " --substeps " + std::to_string(o.substeps) : "") +
                              (o.input_hold != InputHold::Spline
                                   ? " --input-hold " + to_string(o.input_hold)
                                   : "") +
                              " --params " + o.params + " --excitation " +
                              o.excitation + " --noise " + number_text(o.noise) +
                              " --seed " + std::to_string(o.seed) +
                              (o.resolution > 0.0 ? " --resolution " + number_text(o.resolution) : "") +
                              (o.input_unit.empty() ? "" : " --input-unit " + o.input_unit) +
                              (o.output_unit.empty() ? "" : " --output-unit " + o.output_unit) +
                              " --out " + o.out;
  s.truth["generated_by"] = command;
  s.truth["units"] = {{"t", "s"}, {"u", o.input_unit}, {"y", o.output_unit}};
  const std::string kind = o.model.empty() ? "Hammerstein (MFC-like)" : "model " + o.model;
  write_measurement(o.out, s.data,
                    {"Synthetic " + kind + " data; true parameters and noise floor in " +
                         truth_path.filename().string(),
                     "Regenerate: " + command});
  write_file_atomic(truth_path, s.truth.dump(2) + "\n");
  std::cout << "wrote " << o.out << " (" << s.data.size() << " samples) and " << truth_path.string()
            << " (noise-floor SSE " << s.truth["noise_floor_sse"].get<double>() << ")\n";
}

}  // namespace

Action add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  auto* cmd = app.add_subcommand(
      "simulate", "Write a synthetic measurement CSV from true parameters (of the 13-parameter "
                  "Hammerstein model, or of a --model of effects), an excitation spec and seeded "
                  "Gaussian noise, with DATA.truth.json beside it");
  cmd->add_option("--params", o->params,
                  "JSON file with the 13 parameters (alpha ... d), or with --model the physical "
                  "value of every parameter {\"gain\": .., \"hysteresis.A\": .., ...}")
      ->required();
  cmd->add_option("--model", o->model,
                  "simulate this list of effects (e.g. hysteresis,asymmetry,msd,creep) instead of "
                  "the Hammerstein seed model");
  cmd->add_option("--substeps", o->substeps,
                  "integration sub-steps per sample of ODE effects (0: each effect's default)")
      ->capture_default_str()->check(number_range(0, 1000, kSubstepsHint));
  cli::add_input_hold_option(cmd, o->input_hold, "as a stream runs the model");
  cmd->add_option("--excitation", o->excitation, "JSON excitation spec (sine / sweep / steps segments)")
      ->required();
  cmd->add_option("--noise", o->noise, "noise sd as a fraction of the output RMS")
      ->capture_default_str()
      ->check(number_range(0.0, 10.0, "give a fraction of the output RMS from 0 to 10"));
  cmd->add_option("--resolution", o->resolution,
                  "sensor resolution in output units: y is rounded to its multiples after the "
                  "noise (0: none; needs --model)")
      ->capture_default_str()
      ->check(number_range(0.0, 1e6, "give a resolution of 0 (none) or more"));
  cmd->add_option("--seed", o->seed, "noise seed")->capture_default_str();
  cmd->add_option("--form", o->form, "Bouc-Wen form")->capture_default_str()
      ->check(CLI::IsMember({"increment", "paper"}));
  cmd->add_option("--input-unit", o->input_unit, "unit of u, recorded for figure axes (e.g. V)");
  cmd->add_option("--output-unit", o->output_unit, "unit of y, recorded for figure axes (e.g. µm)");
  cmd->add_option("--out", o->out, "output CSV, or MAT file (v7) when the name ends in .mat; the truth file is written beside it")->required();
  add_threads_option(cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    simulate(*o);
  };
}

}  // namespace hystbench::cli
