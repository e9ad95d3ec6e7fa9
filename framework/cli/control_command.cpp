#include <iostream>
#include <memory>
#include <mutex>
#include <omp.h>

#include "framework/cli/commands.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/control/control_figures.hpp"
#include "framework/control/control_report.hpp"
#include "framework/control/control_run.hpp"
#include "framework/control/control_tables.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"

namespace hystbench::cli {
namespace {

struct ControlOptions {
  std::string experiment;
  OutputOptions output;
  int trials = 0;  // 0: the experiment's
  std::uint64_t seed = 0;
  bool seed_given = false;
};

void print_summary(const ControlSetup& setup, const ControlResults& r) {
  for (const auto& e : setup.estimates)
    std::cout << "estimate: " << e.description << " (phase error "
              << format_number("%.1f", e.error.phase_deg) << " deg at the disturbance)\n";
  for (const auto& c : r.controllers) {
    if (c.entry.in_sweep) continue;
    std::cout << "  " << c.entry.label << ": ";
    if (c.all_diverged())
      std::cout << "diverged at " << format_number("%.1f", c.earliest_divergence_s) << " s\n";
    else
      std::cout << "attenuation " << format_number("%.1f", c.truth.mean.attenuation_db)
                << " dB (true), " << format_number("%.1f", c.measured.mean.efficiency_percent)
                << " % efficiency (measured)\n";
  }
}

void control(const ControlOptions& o) {
  ControlExperiment x = ControlExperiment::load(o.experiment);
  if (o.trials > 0) x.trials = o.trials;
  if (o.seed_given) x.seed = o.seed;
  const ControlSetup setup = build_control_setup(x);  // every input error surfaces here
  const auto dir = o.output.prepare("control.json");

  StatusLine status;
  std::mutex m;
  const ControlResults results = run_control(x, setup, [&](int done, int total) {
    std::lock_guard lock(m);
    status.show("control: " + std::to_string(done) + "/" + std::to_string(total) + " runs");
  });
  status.finish();
  write_control_tables(dir, x, results);
  std::string note;
  render_figures(dir, write_control_figures(dir, x, results), note);
  write_file_atomic(dir / "control.json",
                    control_json(x, setup, results, omp_get_max_threads()).dump(2) + "\n");
  print_summary(setup, results);
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "table.md").string() << ", control.json and figures\n";
}

}  // namespace

Action add_control_command(CLI::App& app) {
  auto o = std::make_shared<ControlOptions>();
  auto* cmd = app.add_subcommand(
      "control", "Close a vibration-control loop (FxLMS and variable-step variants) on a "
                 "simulated plant whose control path may hold any hystbench model; writes "
                 "control.json, tables and figures");
  cmd->add_option("experiment", o->experiment, "control experiment JSON (see docs/control.md)")
      ->required();
  cmd->add_option("--trials", o->trials, "noise seeds per controller (default: the experiment's)")
      ->check(number_range(1, 100000, "give 1 to 100000 trials"));
  cmd->add_option_function<std::uint64_t>(
      "--seed", [o](std::uint64_t s) { o->seed = s, o->seed_given = true; },
      "experiment seed (default: the experiment's)");
  add_output_options(cmd, o->output);
  add_threads_option(cmd);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    control(*o);
  };
}

}  // namespace hystbench::cli
