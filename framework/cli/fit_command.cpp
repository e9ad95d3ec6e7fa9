#include <iostream>
#include <memory>
#include <optional>

#include "framework/cli/commands.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/core/error.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/io/atomic_file.hpp"

namespace hystbench::cli {
namespace {

struct FitCommandOptions {
  DataOptions data;
  FitCliOptions fit;
  OutputOptions output;
  std::string model, from_fit;
};

// A fit decided by a start-up transient is worth fitting again with the
// warm-up that removes it. compare, diagnose and discover say so in their
// reports; fit, where a user starts, has only its console.
void print_startup_transient(const FitResult& result, const ModelData& data) {
  Eigen::VectorXd y;
  if (!result.model.simulate(result.x, data, y)) return;
  const StartupTransient t = startup_transient(data, y);
  if (t.dominates) std::cout << t.sentence() << "\n";
}

// The fit --from names, when its model is the one to fit (--model, when
// given, must name it). Counted, not tested for text: `--model ""` is a
// mistake for Model::parse to report.
std::optional<FitRecord> start_fit(const FitCommandOptions& o, const CLI::App& cmd) {
  const bool listed = cmd.count("--model") > 0;
  if (o.from_fit.empty()) {
    if (!listed) throw InputError("fit: give --model LIST, or --from FIT.json to start from a fit");
    return std::nullopt;
  }
  FitRecord start = FitRecord::read(o.from_fit);
  if (listed && Model::parse(o.model).text() != start.model.text())
    throw InputError("fit: --model " + o.model + " is not the model of --from " + o.from_fit + " (" +
                     start.model.text() + "); leave --model out to refit that model");
  return start;
}

void fit(FitCommandOptions& o, const CLI::App& cmd) {
  const std::optional<FitRecord> start = start_fit(o, cmd);
  DataSource source = o.data.source();
  const Measurement m = source.load();
  const auto [model, holdout, data] = fit_subject(o.data, o.fit, cmd, m, start, o.model);
  FitOptions options = o.fit.fit_options();
  const auto dir = o.output.prepare("fit.json");

  StatusLine status;
  options.status = [&](const std::string& s) { status.show("fit " + model.text() + ": " + s); };
  const FitResult result = fit_model(model, data, options, start ? &start->x : nullptr);
  status.finish();

  FitRecord record = make_fit_record(result.model, result.x, data, source, holdout, options.seed);
  nlohmann::json fit_details = options.to_json();
  if (start) fit_details["from"] = o.from_fit;
  fit_details["evaluations_used"] = result.evaluations;
  fit_details["seconds"] = result.seconds;
  fit_details["start_sse"] = result.start_sse;
  record.details["fit"] = fit_details;
  write_file_atomic(dir / "fit.json", record.to_json().dump(2) + "\n");
  print_parameters(record);
  print_errors(fit_errors(result.model, result.x, data), source.y_unit);
  print_startup_transient(result, data);
  std::cout << "wrote " << (dir / "fit.json").string() << "\n";
}

}  // namespace

Action add_fit_command(CLI::App& app) {
  auto o = std::make_shared<FitCommandOptions>();
  auto* cmd = app.add_subcommand(
      "fit", "Fit a model (a list of physical effects) to a measurement: seeded global restarts, "
             "each polished by an NLopt local method; writes DIR/fit.json");
  add_data_options(cmd, o->data);
  cmd->add_option("--model", o->model,
                  "effects in signal-chain order, e.g. hysteresis,asymmetry,msd,arx "
                  "(`hystbench list effects` lists them); with --from, that fit's model");
  cmd->add_option("--from", o->from_fit,
                  "start from this fit.json: its parameters are one more start, polished before the "
                  "restarts (the result is never worse than it on the estimation samples), with its scales, "
                  "warm-up, initial state, sub-steps and input hold unless given; e.g. a fit refitted "
                  "under another --input-hold");
  add_fit_options(cmd, o->fit);
  add_output_options(cmd, o->output);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, cmd, load_plugins] {
    load_plugins();
    fit(*o, *cmd);
  };
}

}  // namespace hystbench::cli
