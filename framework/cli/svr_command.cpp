#include <iostream>
#include <memory>
#include <omp.h>

#include "framework/cli/commands.hpp"
#include "framework/cli/experiment_records.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/text.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/report/figures.hpp"
#include "framework/svr/svr_figures.hpp"
#include "framework/svr/svr_report.hpp"

namespace hystbench::cli {
namespace {

struct SvrOptions {
  std::string experiment;
  OutputOptions output;
  std::uint64_t seed = 0;
  bool seed_given = false;
};

void print_summary(const SvrExperiment& x, const SvrResults& r) {
  const SvrHyperparameters& h = r.search.hyperparameters;
  std::cout << "hyperparameters: epsilon " << format_number("%.4g", h.epsilon) << ", C "
            << format_number("%.4g", h.C) << ", sigma " << format_number("%.4g", h.sigma) << " (gamma "
            << format_number("%.4g", h.gamma()) << "), " << r.model.regressor().support_vectors()
            << " support vectors";
  if (x.stage2) std::cout << "; ARX orders p = " << r.arx.best.p << ", q = " << r.arx.best.q << " by AIC";
  std::cout << "\n";
  for (const SvrTestRow& row : r.rows) {
    std::cout << "  " << row.signal->label << ": SVR RMSE " << quantity(row.svr.rmse, x.y_unit) << ", RE "
              << format_number("%.2f", 100 * row.svr.re) << " %";
    if (row.greybox)
      std::cout << "; grey-box RMSE " << quantity(row.greybox->rmse, x.y_unit) << ", RE "
                << format_number("%.2f", 100 * row.greybox->re) << " %";
    std::cout << "\n";
  }
}

void svr(const SvrOptions& o) {
  SvrExperiment x = load_with_records<SvrExperiment>(o.experiment, std::cout);  // every input error surfaces here
  if (o.seed_given) x.search.seed = o.seed;
  const auto dir = o.output.prepare("svr.json");
  const int threads = omp_get_max_threads();
  StatusLine status;
  const SvrResults r = run_svr(x, threads, [&](const std::string& s) { status.show("svr: " + s); });
  status.finish();
  write_svr_report(dir, x, r, threads);
  std::string note;
  render_figures(dir, write_svr_figures(dir, x, r), note);
  print_summary(x, r);
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "table.md").string() << ", svr.json, svr_model.json and figures\n";
}

}  // namespace

Action add_svr_command(CLI::App& app) {
  auto o = std::make_shared<SvrOptions>();
  auto* cmd = app.add_subcommand(
      "svr", "Identify the SVR Hammerstein-like model of seed 002 (epsilon-SVR NARX tuned by an optimizer "
             "plugin, then ARX by AIC) and score it, beside a grey-box fit, on every test signal; writes "
             "svr_model.json, svr.json, aic.csv, tables and loop figures");
  cmd->add_option("experiment", o->experiment, "SVR experiment JSON (see docs/svr.md)")->required();
  cmd->add_option_function<std::uint64_t>(
      "--seed", [o](std::uint64_t s) { o->seed = s, o->seed_given = true; },
      "seed of the hyperparameter search (default: the experiment's)");
  add_output_options(cmd, o->output);
  add_threads_option(cmd);
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    svr(*o);
  };
}

}  // namespace hystbench::cli
