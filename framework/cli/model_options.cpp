#include "framework/cli/model_options.hpp"

#include <filesystem>

#include "framework/cli/commands.hpp"
#include "framework/cli/input_hold_option.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/error.hpp"

namespace hystbench::cli {

DataSource DataOptions::source() const {
  DataSource s;
  s.path = data;
  if (!columns.empty()) s.columns = ColumnMap::parse(columns);
  s.columns.delimiter = ColumnMap::parse_delimiter(delimiter);
  s.u_unit = input_unit;
  s.y_unit = output_unit;
  return s;
}

HoldoutSpec DataOptions::holdout_spec() const {
  HoldoutSpec spec = HoldoutSpec::parse(holdout);
  // Else the hold-out text's own (auto+warmup:N+held), or 0 and rest.
  if (warmup) spec.warmup = *warmup;
  if (initial_state) spec.held_start = *initial_state == "held";
  return spec;
}

void DataOptions::take_start(HoldoutSpec& spec, const HoldoutSpec& fit) const {
  if (warmup)
    spec.warmup = *warmup;
  else if (spec.warmup == 0)
    spec.warmup = fit.warmup;
  if (initial_state)
    spec.held_start = *initial_state == "held";
  else if (!spec.held_start)
    spec.held_start = fit.held_start;
}

bool fitted_on(const FitRecord& fit, const DataSource& source) {
  std::error_code ec;
  return std::filesystem::equivalent(source.path, fit.data.path, ec);
}

ModelData data_for_fit(const DataOptions& o, const FitRecord& fit, DataSource& source, bool holdout_given,
                       HoldoutSpec::Mode elsewhere) {
  if (o.columns.empty()) {
    const char given = source.columns.delimiter;
    source.columns = fit.data.columns;
    if (given) source.columns.delimiter = given;
  }
  if (source.u_unit.empty()) source.u_unit = fit.data.u_unit;
  if (source.y_unit.empty()) source.y_unit = fit.data.y_unit;
  const Measurement m = source.load();
  HoldoutSpec holdout;
  if (holdout_given)
    holdout = o.holdout_spec();
  else if (fitted_on(fit, source))
    holdout = fit.holdout;
  else
    holdout.mode = elsewhere;
  o.take_start(holdout, fit.holdout);
  return prepare_model_data(m, fit.scales, holdout);
}

void add_data_options(CLI::App* cmd, DataOptions& o, bool with_holdout) {
  cmd->add_option("--data", o.data, "measurement CSV (columns t, u, y, optional segment) or MAT file (vectors t, u, y)")
      ->required();
  cmd->add_option("--columns", o.columns,
                  "column names when they are not t, u, y or a common name (time/zeit, "
                  "voltage/spannung/input, displacement/weg/position/output), e.g. "
                  "t=t_s,u=u_N,y=y_m");
  cmd->add_option("--delimiter", o.delimiter,
                  "between fields: comma, semicolon or tab (default: the header's; with ';' or "
                  "tab, decimal commas are read)");
  cmd->add_option("--input-unit", o.input_unit,
                  "unit of u for reports (default: from DATA.truth.json, else the header, e.g. "
                  "voltage [V])");
  cmd->add_option("--output-unit", o.output_unit,
                  "unit of y for reports (default: from DATA.truth.json, else the header)");
  cmd->add_option("--warmup", o.warmup,
                  "leading samples that only initialise the model (a start-up transient, an "
                  "unknown initial state): simulated, never fitted or scored (benchmarks: "
                  "Silverbox 50, cascaded tanks 5; default 0, or the fit's own)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--initial-state", o.initial_state,
                  "rest: the model starts at rest; held: where a long-held input leaves it, at "
                  "the level that matches the warm-up samples (a record that starts mid-way, "
                  "e.g. a tank half full; needs --warmup; default rest, or the fit's own)")
      ->check(CLI::IsMember({"rest", "held"}));
  if (with_holdout)
    cmd->add_option("--holdout", o.holdout,
                    "samples never used for fitting: auto (the last quarter of every segment, so "
                    "the held-out part spans the fitted band), none, last:FRACTION, "
                    "segments:A,B, by-frequency (whole segments spread over the band: a test "
                    "of extrapolation)")
        ->capture_default_str();
}

FitSubject fit_subject(const DataOptions& data, const FitCliOptions& fit, const CLI::App& cmd, const Measurement& m,
                       const std::optional<FitRecord>& start, const std::string& list) {
  HoldoutSpec holdout = data.holdout_spec();
  if (start) data.take_start(holdout, start->holdout);
  Model model = start ? start->model : Model::parse(list);
  // A fit is used as it was made, unless the command line says otherwise.
  if (!start || cmd.count("--substeps")) model.set_substeps(fit.substeps);
  if (!start || cmd.count("--input-hold")) model.set_input_hold(fit.input_hold);
  ModelData d = prepare_fit_data(m, start ? start->scales : SignalScales::of(m), holdout, model);
  return {std::move(model), holdout, std::move(d)};
}

FitOptions FitCliOptions::fit_options() const {
  FitOptions f = fit;
  try {
    f.optimizer_params = nlohmann::json::parse(optimizer_params);
  } catch (const nlohmann::json::exception& e) {  // syntax, or a number beyond a double
    throw InputError("--optimizer-params: not valid JSON: " + std::string(e.what()));
  }
  f.validate();
  return f;
}

void add_fit_options(CLI::App* cmd, FitCliOptions& o) {
  cmd->add_option("--optimizer", o.fit.optimizer, "global optimizer (see `hystbench list`)")
      ->capture_default_str();
  cmd->add_option("--optimizer-params", o.optimizer_params,
                  "its parameters as JSON, e.g. '{\"restarts\": \"none\"}'")
      ->capture_default_str();
  cmd->add_option("--evaluations", o.fit.evaluations,
                  "global evaluations per restart (0: 2500 per parameter, at least 10000)")
      ->capture_default_str()
      ->check(number_range(0, kUnbounded, "give a positive number of evaluations (0 = default)"));
  cmd->add_option("--restarts", o.fit.restarts, "seeded global restarts")
      ->capture_default_str()->check(number_range(0, 1000, "give 0 to 1000 restarts"));
  cmd->add_option("--local", o.fit.local, "NLopt local method of the polish")->capture_default_str();
  cmd->add_option("--local-evaluations", o.fit.local_evaluations,
                  "polish evaluations per start (0: 300 per parameter, at least 1000)")
      ->capture_default_str()
      ->check(number_range(0, kUnbounded,
                           "give a positive number of polish evaluations (0 = default)"));
  cmd->add_option("--seed", o.fit.seed, "seed of every random choice")->capture_default_str();
  add_threads_option(cmd);
  cmd->add_option("--substeps", o.substeps,
                  "integration sub-steps per sample of ODE effects (0: each effect's default)")
      ->capture_default_str()->check(number_range(0, 1000, kSubstepsHint));
  add_input_hold_option(cmd, o.input_hold, "the model then streams exactly as fitted");
}

DiagnoseOptions DiagnoseCliOptions::diagnose_options(FitOptions fit, const DataSource& source) const {
  DiagnoseOptions d;
  d.fit = std::move(fit);
  if (!candidates.empty()) {
    // Model::parse checks each name against the catalog and refuses repeats.
    d.candidates = Model::parse(candidates, "--candidates").effects();
  }
  d.bic_threshold = bic_threshold;
  d.heldout_gain = heldout_gain;
  d.candidate_restarts = candidate_restarts;
  d.u_unit = source.u_unit;
  d.y_unit = source.y_unit;
  return d;
}

void add_diagnose_options(CLI::App* cmd, DiagnoseCliOptions& o) {
  cmd->add_option("--candidates", o.candidates,
                  "effects to try, comma-separated (default: every effect not in the model)");
  cmd->add_option("--bic-threshold", o.bic_threshold,
                  "a candidate is significant when its BIC change is at or below this")
      ->capture_default_str()
      ->check(number_range(-kUnbounded, 0.0,
                           "give a BIC change of 0 or below (lower is stricter)"));
  cmd->add_option("--heldout-gain", o.heldout_gain,
                  "... and its held-out RMSE falls by at least this fraction")
      ->capture_default_str()->check(number_range(0.0, 0.99, "give a fraction from 0 to 0.99"));
  cmd->add_option("--candidate-restarts", o.candidate_restarts,
                  "global restarts of each extended model besides its warm refit")
      ->capture_default_str()->check(number_range(0, 100, "give 0 to 100 restarts"));
}

std::filesystem::path OutputOptions::prepare(const std::string& marker) const {
  namespace fs = std::filesystem;
  const fs::path dir(out);
  std::error_code ec;
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError("--out " + out + ": exists and is not a folder");
  if (fs::exists(dir / marker) && !force)
    throw InputError("--out " + out + ": already holds " + marker +
                     "; pass --force to replace it or choose another folder");
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + out + ": cannot create this folder: " + ec.message());
  return dir;
}

void add_output_options(CLI::App* cmd, OutputOptions& o) {
  cmd->add_option("--out", o.out, "folder for the results")->required();
  cmd->add_flag("--force", o.force, "replace earlier results in --out");
  add_figure_style_option(*cmd);
}

}  // namespace hystbench::cli
