#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "framework/cli/commands.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/svr_comparison.hpp"
#include "framework/core/error.hpp"
#include "framework/discovery/diagnosis_report.hpp"
#include "framework/discovery/ladder_report.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/io/json_file.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench::cli {
namespace {

struct DiagnoseCommandOptions {
  DataOptions data;
  FitCliOptions fit;
  DiagnoseCliOptions diagnose;
  OutputOptions output;
  std::string model, from_fit;
};

void print_diagnosis(const Diagnosis& d, const std::string& unit) {
  std::cout << "model " << d.model.text() << ": ";
  print_errors(d.errors, unit);
  std::cout << d.where.excitation.summary() << "\n";
  std::cout << "candidates (best first; * significant: ΔBIC at or below the threshold and a lower held-out "
               "error):\n";
  for (const auto& c : d.candidates)
    std::cout << "  " << (c.significant ? "* " : "  ") << c.effect << "  dBIC "
              << c.delta_bic << "  RMSE " << c.after.rmse_estimation << "  held-out "
              << c.after.rmse_heldout << "\n";
  std::cout << "verdict: " << d.verdict << "\n";
  if (const Candidate* w = d.winner()) std::cout << w->evidence << "\n";
}

// A black-box model has no chain to add an effect to, so no candidate is
// refitted: the report holds the where-it-fails breakdowns and every
// effect's residual signature, which say what physics the residual shows.
void diagnose_svr(const DiagnoseCommandOptions& o, const nlohmann::json& file, const CLI::App& cmd) {
  const Comparison c = compare_svr_model(file, o.from_fit, o.data, o.output, cmd);
  std::cout << "residual signatures (report.md, metrics.json):\n";
  for (const EffectSignature& s : c.signatures)
    if (!s.sentence.empty()) std::cout << "  " << s.effect << ": " << s.sentence << "\n";
  std::cout << "candidates: none tried. diagnose refits a catalog chain with each missing effect added; "
               "an SVR model has no chain to extend. Fit a catalog model to the same data (hystbench fit "
               "or discover) to test an effect.\n";
}

void run_diagnose(DiagnoseCommandOptions& o, const CLI::App& cmd) {
  // Counted, not tested for text: `--model ""` is a mistake to report, not a missing option.
  if ((cmd.count("--model") > 0) == (cmd.count("--fit") > 0))
    throw InputError("diagnose: give either --model LIST (fit it first) or --fit FIT.json");
  if (cmd.count("--fit")) {
    const nlohmann::json file = read_json_file(o.from_fit, "model file");
    if (SvrHammerstein::is_model_file(file)) return diagnose_svr(o, file, cmd);
  }
  DataSource source = o.data.source();
  const Measurement m = source.load();
  StatusLine status;
  FitOptions fit = o.fit.fit_options();
  DiagnoseOptions options = o.diagnose.diagnose_options(fit, source);
  // Either a fit to start from (its scales, so its parameters keep their
  // meaning) or a model to fit first.
  std::optional<FitRecord> start;
  if (cmd.count("--fit")) start = FitRecord::read(o.from_fit);
  const auto [model, holdout, data] = fit_subject(o.data, o.fit, cmd, m, start, o.model);
  const auto dir = o.output.prepare("diagnosis.json");
  options.fit.status = [&](const std::string& s) { status.show("diagnose " + model.text() + ": " + s); };

  const Eigen::VectorXd x = start ? start->x : fit_model(model, data, options.fit).x;
  const Diagnosis d = diagnose(model, x, data, options);
  status.finish();
  std::string note;
  write_diagnosis(dir, d, data, source, holdout, note);
  // Fitted here from the data's own scales, the diagnosis is the first rung
  // `discover --start` would climb from: `discover --diagnosis` reuses it.
  if (!start)
    write_first_step(dir, d, {data, source, holdout, std::nullopt,
                              first_step_options(model, options, o.fit.substeps)});
  else  // a rung left by an earlier run into this folder would not match this report
    std::filesystem::remove(dir / "checkpoint.json");
  print_diagnosis(d, source.y_unit);
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "report.md").string() << " and diagnosis.json"
            << (start ? "" : " (checkpoint.json: discover --diagnosis starts from it)") << "\n";
}

}  // namespace

Action add_diagnose_command(CLI::App& app) {
  auto o = std::make_shared<DiagnoseCommandOptions>();
  auto* cmd = app.add_subcommand(
      "diagnose", "Fit a model, then try every catalog effect it lacks (warm-started refits) and "
                  "name the missing one by the drop in BIC and held-out error, with its residual "
                  "evidence; writes diagnosis.json, report.md and figures");
  add_data_options(cmd, o->data);
  cmd->add_option("--model", o->model, "effects of the model to diagnose, e.g. hysteresis,msd");
  cmd->add_option("--fit", o->from_fit,
                  "diagnose this fit.json instead of fitting --model; an svr_model.json (hystbench svr) "
                  "gets its breakdowns and residual signatures, with no candidate refits");
  add_fit_options(cmd, o->fit);
  add_diagnose_options(cmd, o->diagnose);
  add_output_options(cmd, o->output);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, cmd, load_plugins] {
    load_plugins();
    run_diagnose(*o, *cmd);
  };
}

}  // namespace hystbench::cli
