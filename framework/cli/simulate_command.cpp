#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/input_hold_option.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/simulation_recipe.hpp"
#include "framework/cli/threads_option.hpp"

namespace hystbench::cli {
namespace {

void simulate(const SimulationRecipe& o) {
  const SimulatedRecord r = write_simulated_record(o);
  std::cout << "wrote " << o.out << " (" << r.samples << " samples) and " << r.truth.string()
            << " (noise-floor SSE " << r.noise_floor_sse << ")\n";
}

}  // namespace

Action add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulationRecipe>();
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
      ->capture_default_str()->check(number_range(0, kMaxRecipeSubsteps, kSubstepsHint));
  cli::add_input_hold_option(cmd, o->input_hold, "as a stream runs the model");
  cmd->add_option("--excitation", o->excitation, "JSON excitation spec (sine / sweep / steps segments)")
      ->required();
  cmd->add_option("--noise", o->noise, "noise sd as a fraction of the output RMS")
      ->capture_default_str()
      ->check(number_range(0.0, kMaxRecipeNoise, "give a fraction of the output RMS from 0 to 10"));
  cmd->add_option("--resolution", o->resolution,
                  "sensor resolution in output units: y is rounded to its multiples after the "
                  "noise (0: none; needs --model)")
      ->capture_default_str()
      ->check(number_range(0.0, kMaxRecipeResolution, "give a resolution of 0 (none) or more"));
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
