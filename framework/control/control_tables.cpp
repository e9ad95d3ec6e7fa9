#include "framework/control/control_tables.hpp"

#include <cmath>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/results_readme.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

using table::Format;

struct Column {
  const char* markdown;
  const char* latex;
  double SuppressionMetrics::*field;
  bool truth;
};

const Column kColumns[] = {
    {"RMSE (s.u.)", "RMSE (s.u.)", &SuppressionMetrics::rmse, false},
    {"MAE (s.u.)", "MAE (s.u.)", &SuppressionMetrics::mae, false},
    {"η (%)", "$\\eta$ (\\%)", &SuppressionMetrics::efficiency_percent, false},
    {"RMSE* (s.u.)", "RMSE$^*$ (s.u.)", &SuppressionMetrics::rmse, true},
    {"MAE* (s.u.)", "MAE$^*$ (s.u.)", &SuppressionMetrics::mae, true},
    {"η* (%)", "$\\eta^*$ (\\%)", &SuppressionMetrics::efficiency_percent, true},
    {"Atten.* (dB)", "Atten.$^*$ (dB)", &SuppressionMetrics::attenuation_db, true},
    {"Conv.* (s)", "Conv.$^*$ (s)", &SuppressionMetrics::convergence_s, true},
};

std::string time_text(double s) { return format_number("%.1f", s) + " s"; }

std::string metric_cell(const ControllerResult& r, const Column& c, const ControlExperiment& x,
                        Format f) {
  if (r.all_diverged()) return "diverged at " + time_text(r.earliest_divergence_s);
  const MetricSummary& s = c.truth ? r.truth : r.measured;
  const bool convergence = c.field == &SuppressionMetrics::convergence_s;
  const double mean = s.mean.*c.field;
  if (std::isnan(mean)) return convergence ? "> " + time_text(x.loop.duration_s) : "–";
  std::string cell = table::format_fitness(mean, f);
  const int averaged = int(r.trials.size()) - r.diverged_trials - (convergence ? s.never_converged : 0);
  if (averaged > 1)
    cell += (f == Format::Latex ? " $\\pm$ " : " ± ") + table::format_fitness(s.sd.*c.field, f);
  if (convergence && s.never_converged > 0)
    cell += " (" + std::to_string(s.never_converged) + " never)";
  return cell;
}

std::string diverged_cell(const ControllerResult& r) {
  if (r.diverged_trials == 0) return "no";
  return std::to_string(r.diverged_trials) + " of " + std::to_string(r.trials.size()) +
         ", first at " + time_text(r.earliest_divergence_s);
}

// Short, for a paper; control_method() says how each column is computed.
std::string caption(const ControlExperiment& x, bool sweep, bool any_reconstructed, Format f) {
  const bool md = f == Format::Markdown;
  std::string text = (sweep ? "Fixed-step sweep of " : "Vibration control, ") +
                     (md ? "`" + x.name + "`" : "\\texttt{" + table::escape_latex(x.name) + "}") + ": " +
                     std::to_string(x.trials) + " noise seeds, " + number_text(x.loop.duration_s) + " s at " +
                     number_text(x.loop.sample_rate_hz) + " Hz; mean " + (md ? "±" : "$\\pm$") +
                     " sd over the runs that did not diverge. s.u.: sensor units (disturbance amplitude 1). "
                     "Starred: noise-free error.";
  if (any_reconstructed) text += (md ? " †: reconstructed rule." : " $\\dagger$: reconstructed rule.");
  return text;
}

std::string control_method(const ControlExperiment& x) {
  return "Each controller runs " + std::to_string(x.trials) + " times, each with its own sensor noise "
         "(experiment seed " + std::to_string(x.seed) + "); a cell is the mean and standard deviation over the runs that did not "
         "diverge. RMSE and MAE are in sensor units, in which the disturbance alone has amplitude 1 (RMS "
         "0.707) at the sensor. Efficiency η and attenuation compare the RMS of the last " +
         number_text(x.windows.steady_s) + " s with the uncontrolled run of the same noise; convergence "
         "is the time after which the 1 s moving RMS stays below -20 dB. Starred columns use the "
         "noise-free (true) error, the others the measured one. Ŝ phase err. is the phase error of the "
         "secondary-path estimate at the disturbance frequency. A rule marked † is our reconstruction "
         "(docs/control.md).";
}

// The uncontrolled reference first in the main table, then the controllers.
std::vector<const ControllerResult*> rows(const ControlResults& res, bool sweep) {
  std::vector<const ControllerResult*> out;
  if (!sweep) out.push_back(&res.uncontrolled);
  for (const auto& r : res.controllers)
    if (r.entry.in_sweep == sweep) out.push_back(&r);
  return out;
}

table::CellTable make_table(const ControlExperiment& x, const ControlResults& res, bool sweep,
                            Format f) {
  table::CellTable t;
  t.label = table::label_key(x.name + (sweep ? "-sweep" : ""));
  t.header.push_back(sweep ? (f == Format::Latex ? table::escape_latex(x.sweep_param) : x.sweep_param)
                           : "Controller");
  for (const Column& c : kColumns) t.header.push_back(f == Format::Latex ? c.latex : c.markdown);
  t.header.push_back(f == Format::Latex ? "$\\hat S$ phase err. ($^\\circ$)" : "Ŝ phase err. (°)");
  t.header.push_back("Diverged");
  bool any_reconstructed = false;
  for (const ControllerResult* row : rows(res, sweep)) {
    const ControllerResult& r = *row;
    any_reconstructed |= r.entry.reconstructed;
    const std::string dagger = r.entry.reconstructed ? (f == Format::Latex ? "$^\\dagger$" : " †") : "";
    std::vector<std::string> cells{
        sweep ? number_text(r.entry.sweep_value) : table::escape(r.entry.label, f) + dagger};
    for (const Column& c : kColumns) cells.push_back(metric_cell(r, c, x, f));
    cells.push_back(r.estimate ? format_number("%.1f", r.estimate->error.phase_deg) : "–");
    cells.push_back(diverged_cell(r));
    t.rows.push_back(std::move(cells));
  }
  t.caption = caption(x, sweep, any_reconstructed, f);
  return t;
}

std::string csv(const ControlResults& res, bool sweep) {
  std::string out = "label,controller";
  for (const char* kind : {"measured", "true"})
    for (const auto& m : kSuppressionMetrics)
      for (const char* stat : {"mean", "sd"})
        out.append(",").append(kind).append("_").append(m.name).append("_").append(stat);
  out += ",estimate_phase_error_deg,diverged_trials,trials,earliest_divergence_s\n";
  for (const ControllerResult* row : rows(res, sweep)) {
    const ControllerResult& r = *row;
    out += csv_field(r.entry.label) + "," + csv_field(r.entry.name);
    for (const MetricSummary* s : {&r.measured, &r.truth})
      for (const auto& m : kSuppressionMetrics)
        out.append(",").append(csv_number(s->mean.*m.field)).append(",").append(csv_number(s->sd.*m.field));
    out.append(",").append(r.estimate ? csv_number(r.estimate->error.phase_deg) : "");
    out.append(",").append(std::to_string(r.diverged_trials)).append(",").append(std::to_string(r.trials.size()));
    out.append(",").append(csv_number(r.earliest_divergence_s)).append("\n");
  }
  return out;
}

}  // namespace

std::vector<std::filesystem::path> write_control_tables(const std::filesystem::path& dir,
                                                        const ControlExperiment& x,
                                                        const ControlResults& res) {
  std::vector<std::filesystem::path> written;
  for (bool sweep : {false, true}) {
    if (sweep && x.sweep_param.empty()) continue;
    const std::string stem = sweep ? "step_sweep" : "table";
    write_file_atomic(dir / (stem + ".md"), table::markdown(make_table(x, res, sweep, Format::Markdown)));
    write_file_atomic(dir / (stem + ".tex"), table::latex(make_table(x, res, sweep, Format::Latex)));
    write_file_atomic(dir / (stem + ".csv"), csv(res, sweep));
    for (const char* ext : {".md", ".tex", ".csv"}) written.push_back(dir / (stem + ext));
  }
  std::vector<TableMethod> methods{{"table", control_method(x)}};
  if (!x.sweep_param.empty()) methods.push_back({"step_sweep", "The same columns for each fixed value of " +
                                                                   x.sweep_param + ". " + control_method(x)});
  write_results_readme(dir, "Made by `hystbench control` from the experiment `" + x.name +
                                "` (in `control.json` with every run's numbers).", methods);
  written.push_back(dir / "README.md");
  return written;
}

}  // namespace hystbench
