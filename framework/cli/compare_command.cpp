#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/mat_option.hpp"
#include "framework/cli/comparison_output.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/svr_comparison.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/io/json_file.hpp"
#include "framework/model/held_start.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench::cli {
namespace {

struct CompareOptions {
  DataOptions data;
  OutputOptions output;
  std::string fit, mat;
  int periods = 1;
};

// The data as the fit saw them (data_for_fit); nothing held out on other
// data or over several periods.
ModelData data_for(const CompareOptions& o, const FitRecord& fit, DataSource& source,
                   const CLI::App& cmd) {
  if (o.periods <= 1)
    return data_for_fit(o.data, fit, source, cmd.count("--holdout") > 0, HoldoutSpec::Mode::None);
  DataOptions whole = o.data;
  whole.holdout = "none";
  // The steady state is scored: nothing to warm up, no start to match.
  whole.warmup = whole.warmup.value_or(0);
  whole.initial_state = whole.initial_state.value_or("rest");
  return data_for_fit(whole, fit, source, true, HoldoutSpec::Mode::None);
}

// " (started where u held at 2.31 V leaves it, …)": what a held start
// assumed about the time before the record, so the reader can judge it.
std::string held_start_text(const FitRecord& fit, const ModelData& data, const DataSource& source) {
  double level = 0.0;
  if (!data.held_start || !held_level(fit.model, fit.x, data, level)) return "";
  return " (started where u held at " + format_number("%.4g", level * data.scales.u) + " " + source.u_unit +
         " leaves it: the level that matches the first " + std::to_string(data.warmup) + " samples)";
}

void report(const CompareOptions& o, const DataSource& source, const ModelData& data, Eigen::VectorXd y,
            const FitRecord& fit) {
  const auto dir = o.output.prepare("metrics.json");
  const std::string model_text = fit.model.text();
  write_and_print_comparison(
      dir, source, data, std::move(y), model_text,
      model_text + " on " + o.data.data +
          (o.periods > 1 ? " (periodic steady state, last of " + std::to_string(o.periods) + " periods)"
                         : held_start_text(fit, data, source)),
      o.mat, fitted_on(fit, source) ? ComparisonInput::Record::Fitted : ComparisonInput::Record::Other);
}

void compare(const CompareOptions& o, const CLI::App& cmd) {
  const nlohmann::json file = read_json_file(o.fit, "model file");
  if (SvrHammerstein::is_model_file(file)) {
    if (o.periods > 1) throw InputError("--periodic needs a catalog fit.json; an SVR model runs from measured samples");
    compare_svr_model(file, o.fit, o.data, o.output, cmd, o.mat);
    return;
  }
  const FitRecord fit = FitRecord::read(o.fit);
  DataSource source = o.data.source();
  const ModelData data = data_for(o, fit, source, cmd);
  Eigen::VectorXd y;
  if (!simulate_physical(fit.model, fit.x, data, y, o.periods))
    throw InputError(o.fit + ": the model diverges on " + o.data.data +
                     " (input outside the range it was fitted on?)");
  report(o, source, data, std::move(y), fit);
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare a fitted model (fit.json) with a measurement: metrics overall and by "
                 "segment, amplitude, branch and time, residual whiteness and input correlation, "
                 "noise floor; writes metrics.json, report.md and figures");
  add_data_options(cmd, o->data);
  cmd->add_option("--fit", o->fit,
                  "fit.json written by `hystbench fit` or `discover`, or svr_model.json written by "
                  "`hystbench svr`")
      ->required();
  cmd->add_option("--periodic", o->periods,
                  "the data are one period of a periodic input: simulate this many periods from "
                  "rest and score the last (steady state)")
      ->capture_default_str()->check(number_range(1, 1000, "give 1 to 1000 periods"));
  cmd->add_option("--mat", o->mat,
                  "also write t, u, y, the model output y_model and the residual as this MAT "
                  "file (v7)")
      ->check(mat_file_name());
  add_threads_option(cmd);
  add_output_options(cmd, o->output);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, cmd, load_plugins] {
    load_plugins();
    compare(*o, *cmd);
  };
}

}  // namespace hystbench::cli
