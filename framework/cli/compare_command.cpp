#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/error.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/discovery/noise_floor.hpp"

namespace hystbench::cli {
namespace {

struct CompareOptions {
  DataOptions data;
  OutputOptions output;
  std::string fit;
  int periods = 1;
};

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
}

// The data as the fit saw them: its columns and units unless given, its
// scales, and its hold-out when these are the data it was fitted on.
ModelData data_for(const CompareOptions& o, const FitRecord& fit, DataSource& source,
                   const CLI::App& cmd) {
  if (o.data.columns.empty()) source.columns = fit.data.columns;
  if (source.u_unit.empty()) source.u_unit = fit.data.u_unit;
  if (source.y_unit.empty()) source.y_unit = fit.data.y_unit;
  const Measurement m = source.load();
  HoldoutSpec holdout;
  if (cmd.count("--holdout"))
    holdout = o.data.holdout_spec();
  else if (same_file(source.path, fit.data.path))
    holdout = fit.holdout;
  else
    holdout.mode = HoldoutSpec::Mode::None;
  if (o.periods > 1) holdout.mode = HoldoutSpec::Mode::None;
  return prepare_model_data(m, fit.scales, holdout);
}

void print_part(const char* name, const ErrorMetrics& m, const std::string& unit) {
  // fit % divides by the spread of y about its mean.
  const std::string fit = std::isfinite(m.fit_percent) ? "fit " + quantity(m.fit_percent, "%")
                                                       : "fit % not defined (y is constant)";
  std::cout << "  " << name << ": RMSE " << quantity(m.rmse, unit) << ", " << fit << ", " << m.n
            << " samples\n";
}

void print_headline(const Comparison& metrics, const std::string& unit) {
  // Without a hold-out every sample is an estimation sample: "all" says it.
  if (metrics.parts.heldout) {
    print_part("estimation", metrics.parts.estimation, unit);
    print_part("heldout", *metrics.parts.heldout, unit);
  }
  print_part("all", metrics.parts.all, unit);
  const ComparedNoiseFloor& floor = metrics.noise_floor;
  if (std::isfinite(floor.sigma)) {
    std::cout << "  estimated noise sigma " << quantity(floor.sigma, unit);
    if (std::isfinite(floor.rmse_over_sigma))
      std::cout << " (RMSE / sigma " << quantity(floor.rmse_over_sigma, "") << ")";
    std::cout << "\n";
  } else {
    std::cout << "  noise sigma not estimated (fewer than " << kNoiseFloorFewestSamples
              << " samples)\n";
  }
}

void compare(const CompareOptions& o, const CLI::App& cmd) {
  const FitRecord fit = FitRecord::read(o.fit);
  DataSource source = o.data.source();
  const ModelData data = data_for(o, fit, source, cmd);
  const auto dir = o.output.prepare("metrics.json");
  Eigen::VectorXd y;
  if (!simulate_physical(fit.model, fit.x, data, y, o.periods))
    throw InputError(o.fit + ": the model diverges on " + o.data.data +
                     " (input outside the range it was fitted on?)");
  const auto input = comparison_input(data, std::move(y), source.u_unit, source.y_unit);
  const auto metrics = compare_signals(input);
  const auto files = write_comparison(dir, input, metrics,
                                      "Model " + fit.model.text() + " against " + source.file_name(),
                                      fit.model.text());
  std::cout << "model " << fit.model.text() << " on " << o.data.data
            << (o.periods > 1 ? " (periodic steady state, last of " + std::to_string(o.periods) +
                                    " periods)"
                              : "")
            << "\n";
  print_headline(metrics, source.y_unit);
  std::cout << "wrote " << files.size() << " files in " << dir.string() << " (see report.md)\n";
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare a fitted model (fit.json) with a measurement: metrics overall and by "
                 "segment, amplitude, branch and time, residual whiteness and input correlation, "
                 "noise floor; writes metrics.json, report.md and figures");
  add_data_options(cmd, o->data);
  cmd->add_option("--fit", o->fit, "fit.json written by `hystbench fit` or `discover`")
      ->required();
  cmd->add_option("--periodic", o->periods,
                  "the data are one period of a periodic input: simulate this many periods from "
                  "rest and score the last (steady state)")
      ->capture_default_str()->check(number_range(1, 1000, "give 1 to 1000 periods"));
  add_threads_option(cmd);
  add_output_options(cmd, o->output);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, cmd, load_plugins] {
    load_plugins();
    compare(*o, *cmd);
  };
}

}  // namespace hystbench::cli
