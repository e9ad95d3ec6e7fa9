#include <iostream>
#include <memory>
#include <omp.h>

#include "framework/cli/commands.hpp"
#include "framework/cli/experiment_records.hpp"
#include "framework/cli/fit_summary.hpp"
#include "framework/cli/model_options.hpp"
#include "framework/cli/threads_option.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#ifdef HYSTBENCH_WITH_SLICOT
#include "framework/harness/progress.hpp"
#include "framework/harness/status_line.hpp"
#include "framework/report/figures.hpp"
#include "framework/tracking/tracking_figures.hpp"
#include "framework/tracking/tracking_report.hpp"
#include "problems/robust/fixed_order_hinf.hpp"
#endif

namespace hystbench::cli {
namespace {

struct TrackOptions {
  std::string experiment;
  OutputOptions output;
  std::uint64_t seed = 0;
  bool seed_given = false;
};

#ifdef HYSTBENCH_WITH_SLICOT
void print_summary(const TrackingExperiment& x, const TrackingResults& r) {
  const ControllerDesign& d = r.design;
  std::cout << "design: L(z) ARX(" << r.nominal.p << ", " << r.nominal.q << "), misfit "
            << format_number("%.2g", r.nominal.misfit) << "; gamma_min " << format_number("%.4g", d.gamma_min)
            << ", full order " << d.full.states() << " (norm " << format_number("%.4g", d.full_check.norm)
            << "), reduced to " << d.reduced.states() << " by " << d.reduction << " (norm "
            << format_number("%.4g", d.reduced_check.norm) << ")\n";
  // Above this, L is a poor account of the model's back (not linear, or
  // not of these orders) and the design rests on it.
  if (r.nominal.misfit > 0.3)
    std::cout << "note: L(z) misses the model's linear part by " << format_number("%.2g", r.nominal.misfit)
              << " of its output; see controller.json (nominal) and docs/tracking.md#nominal-model\n";
  if (d.gamma_min >= 1.0)
    std::cout << "note: gamma_min " << format_number("%.3g", d.gamma_min)
              << " >= 1: the weights cannot be met, and robust stability is not guaranteed\n";
  for (const TrackingRow& row : r.rows) {
    std::cout << "  " << row.reference->label << ", " << row.controller->label << ": ARMSE "
              << quantity(row.run.score.armse, x.y_unit) << ", RE " << format_number("%.2f", 100 * row.run.score.re)
              << " %";
    if (!row.status.empty()) std::cout << " (" << row.status << ")";
    std::cout << "\n";
  }
}

void track(const TrackOptions& o) {
  TrackingExperiment x = load_with_records<TrackingExperiment>(o.experiment, std::cout);  // every input error surfaces here
  if (o.seed_given) x.seed = o.seed;
  TrackingResults r = design_tracking(x);  // an impossible design is bad input too
  const auto dir = o.output.prepare("tracking.json");
  StatusLine status;
  const int threads = omp_get_max_threads();
  run_tracking_rows(x, r, [&](const std::string& s) { status.show("track: " + s); });
  status.finish();
  write_tracking_report(dir, x, r, threads);
  std::string note;
  render_figures(dir, write_tracking_figures(dir, x, r), note);
  print_summary(x, r);
  if (!note.empty()) std::cout << note << "\n";
  std::cout << "wrote " << (dir / "table.md").string() << ", controller.json, tracking.json and figures\n";
}
#else
void track(const TrackOptions&) {
  throw InputError("track: this hystbench was built without SLICOT, which the H-infinity design needs; install "
                   "libslicot-dev and liblapack-dev (scripts/install-deps.sh does) and build again");
}
#endif

}  // namespace

Action add_track_command(CLI::App& app) {
#ifdef HYSTBENCH_WITH_SLICOT
  link_fixed_order_hinf();  // `hystbench run` offers the problem too
#endif
  auto o = std::make_shared<TrackOptions>();
  auto* cmd = app.add_subcommand(
      "track", "Track references with an identified model (seed 002): inverse compensation of its front, a "
               "2DOF H-infinity controller (mixed sensitivity through SLICOT, reduced by balanced stochastic "
               "truncation) and a PI baseline, on a simulated actuator; writes controller.json, tracking.json, "
               "tables in the layout of seed 002's Table 2 and figures");
  cmd->add_option("experiment", o->experiment, "tracking experiment JSON (see docs/tracking.md)")->required();
  cmd->add_option_function<std::uint64_t>(
      "--seed", [o](std::uint64_t s) { o->seed = s, o->seed_given = true; },
      "seed of the sensor noise and the nominal model's excitation (default: the experiment's)");
  add_output_options(cmd, o->output);
  add_threads_option(cmd);
  add_quiet_option(*cmd);
  return [o] { track(*o); };
}

}  // namespace hystbench::cli
