#include <iostream>
#include <memory>
#include <optional>

#include "framework/cli/commands.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/discovery/ladder_report.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/io/truth_file.hpp"

namespace hystbench::cli {
namespace {

struct DiscoverCommandOptions {
  DataOptions data;
  FitCliOptions fit;
  DiagnoseCliOptions diagnose;
  OutputOptions output;
  std::string start = "none";
  int max_steps = 8, refit_restarts = 1;
};

std::optional<double> true_noise_sd(const std::string& data_path) {
  const auto truth = read_truth(data_path);
  const auto noise = truth.value("noise", nlohmann::json::object());
  if (noise.is_object() && noise.value("sd", nlohmann::json()).is_number())
    return noise["sd"].get<double>();
  return std::nullopt;
}

void run_discover(DiscoverCommandOptions& o) {
  DataSource source = o.data.source();
  const Measurement m = source.load();
  const HoldoutSpec holdout = o.data.holdout_spec();
  Model start = Model::parse(o.start, "--start");
  start.set_substeps(o.fit.substeps);
  const ModelData data = prepare_fit_data(m, SignalScales::of(m), holdout, start);
  DiscoverOptions options;
  options.diagnose = o.diagnose.diagnose_options(o.fit.fit_options(), source);
  options.max_steps = o.max_steps;
  options.refit_restarts = o.refit_restarts;
  const auto dir = o.output.prepare("ladder.json");

  StatusLine status(stderr_is_terminal());
  int step = 0;
  options.diagnose.fit.status = [&](const std::string& s) {
    status.show("discover step " + std::to_string(step) + ": " + s);
  };
  const std::string unit = source.y_unit;
  const Ladder ladder = discover(start, data, options, [&](const LadderStep& s, const Diagnosis& d) {
    status.finish();
    std::cout << "step " << step++ << (s.added.empty() ? "" : " (+" + s.added + ")") << ": "
              << s.model.text() << "  ";
    print_errors(s.errors, unit);
    std::cout << "  verdict: " << d.verdict << "\n";
  });
  status.finish();
  const LadderContext ctx{data, source, holdout, true_noise_sd(source.path),
                          {{"fit", options.diagnose.fit.to_json()},
                           {"diagnose", options.diagnose.to_json()},
                           {"max_steps", o.max_steps},
                           {"refit_restarts", o.refit_restarts}}};
  std::string note;
  write_ladder(dir, ladder, ctx, note);
  std::cout << "final model: " << ladder.steps.back().model.text() << "\n";
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "ladder.md").string() << ", ladder.json and fit.json\n";
}

}  // namespace

Action add_discover_command(CLI::App& app) {
  auto o = std::make_shared<DiscoverCommandOptions>();
  auto* cmd = app.add_subcommand(
      "discover", "From a start model, repeat diagnose -> add the missing effect -> refit until "
                  "nothing significant is missing; writes ladder.json, ladder.md, a figure of the "
                  "error falling, each step's diagnosis and the final fit.json");
  add_data_options(cmd, o->data);
  cmd->add_option("--start", o->start, "effects of the start model (\"none\": the gain alone)")
      ->capture_default_str();
  cmd->add_option("--max-steps", o->max_steps, "effects added at most")
      ->capture_default_str()->check(number_range(0, 50, "give 0 to 50 steps"));
  cmd->add_option("--refit-restarts", o->refit_restarts,
                  "global restarts of each extended model that compete with its warm refit")
      ->capture_default_str()->check(number_range(0, 100, "give 0 to 100 restarts"));
  add_fit_options(cmd, o->fit);
  add_diagnose_options(cmd, o->diagnose);
  add_output_options(cmd, o->output);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    run_discover(*o);
  };
}

}  // namespace hystbench::cli
