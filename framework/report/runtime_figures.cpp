#include "framework/report/runtime_figures.hpp"

#include <cstdio>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/stats/runtime_measures.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {

// The palette of the convergence figure, so an algorithm keeps its colour.
constexpr std::array<const char*, 7> kPalette{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                              "#E69F00", "#56B4E9", "#000000"};

std::string colour(std::size_t k) {
  return std::string(" lc rgb \"") + kPalette[k % kPalette.size()] + "\"";
}

std::string block_header(std::size_t index, const std::string& label, const std::string& cols) {
  std::string one_line = label;
  std::replace_if(one_line.begin(), one_line.end(), [](char c) { return c == '\n' || c == '\r'; },
                  ' ');
  return (index ? "\n\n" : "") + std::string("# index ") + std::to_string(index) + ": " +
         one_line + "\n# " + cols + "\n";
}

long last_evaluation(const std::vector<std::vector<TrialResult>>& results) {
  long last = 1;
  for (const auto& trials : results)
    for (const auto& r : trials) {
      last = std::max(last, r.evaluations);
      if (!r.trace.empty()) last = std::max(last, r.trace.back().evaluations);
    }
  return last;
}

// The steps of one algorithm, starting at 0 and carried on to the last
// evaluation of the campaign so that every line spans the whole axis.
std::vector<stats::EcdfStep> ecdf_steps(const std::vector<TrialResult>& trials, double target,
                                        long last) {
  std::vector<stats::EcdfStep> steps{{1, 0.0}};
  if (trials.empty()) return steps;
  std::vector<stats::TrialRecord> records;
  // A failed trial never reaches the target, as in the statistics table.
  for (const auto& r : trials)
    records.push_back({r.evaluations, r.failed() ? std::vector<TracePoint>{} : r.trace});
  for (const auto& s : stats::runtime_ecdf(records, target)) steps.push_back(s);
  steps.push_back({last, steps.back().fraction});
  return steps;
}

std::string ecdf_plot(const Experiment& e) {
  std::string plot = "  plot \\\n";
  for (std::size_t k = 0; k < e.algorithms.size(); ++k) {
    plot += "    \"ecdf.dat\" index " + std::to_string(k) + " using 1:2 with steps lw 2 dt " +
            std::to_string(1 + k / kPalette.size()) + colour(k) + " title " +
            gnuplot::quoted(e.algorithms[k].label) + " noenhanced";
    plot += k + 1 < e.algorithms.size() ? ", \\\n" : "\n";
  }
  return plot;
}

// The target in a title: enough digits to tell it from the noise floor.
std::string four_digits(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string ecdf_settings(const ReportContext& ctx, double target) {
  return "set title " + gnuplot::quoted("Runtime ECDF — " + ctx.experiment + " (" + ctx.problem + ")") +
         ".\"\\n\"." +
         gnuplot::quoted("fraction of " + std::to_string(ctx.trials) +
                         " trials with best fitness <= " + four_digits(target)) +
         " noenhanced\n"
         "set xlabel \"Function evaluations\"\nset ylabel \"Share of trials at target\"\n"
         "set logscale x\nset format x \"10^{%L}\"\nset autoscale xfix\nset offsets graph 0.05, graph 0.02, 0, 0\n"
         "set yrange [0:1.02]\nset grid xtics ytics lt 1 lc rgb \"#e0e0e0\" lw 1\n" +
         gnuplot::key_above_plot();
}

// Every line flat at 0 reads like a broken figure; say why instead.
std::string nobody_reached(double target) {
  const std::string text = "no trial reached the target f ≤ " + four_digits(target);
  return "# " + text + ": every line stays at 0.\n"
         "set label 1 " + gnuplot::quoted(text) +
         " at graph 0.5, graph 0.5 center front noenhanced font \",14\"\n";
}

// Final fitness of the trials whose optimizer did not throw.
std::vector<double> finals(const std::vector<TrialResult>& trials) {
  std::vector<double> out;
  for (const auto& r : trials)
    if (!r.failed() && std::isfinite(r.best)) out.push_back(r.best);
  return out;
}

// The x axis holds about 80 characters: labels that need more room than an
// algorithm's share of it would overlap, so they are turned.
bool labels_crowd(const Experiment& e) {
  std::size_t longest = 0;
  for (const auto& a : e.algorithms) longest = std::max(longest, a.label.size());
  return (longest + 1) * e.algorithms.size() > 80;
}

std::string boxplot_settings(const Experiment& e, const ReportContext& ctx, bool log_y,
                             bool decades) {
  std::string tics;
  for (std::size_t k = 0; k < e.algorithms.size(); ++k)
    tics += (k ? ", " : "") + gnuplot::quoted(e.algorithms[k].label) + " " + std::to_string(k + 1);
  std::string s = "set title " + gnuplot::quoted("Final fitness — " + ctx.experiment + " (" +
                                                ctx.problem + ")") +
                  ".\"\\n\"." +
                  gnuplot::quoted("box: quartiles, whiskers: 1.5 IQR, over " +
                                  std::to_string(ctx.trials) + " trials") +
                  " noenhanced\nset ylabel " + gnuplot::quoted(ctx.fitness_axis("Final best fitness")) +
                  "\n"
                  "set xtics (" + tics + ") noenhanced" +
                  (labels_crowd(e) ? " rotate by 45 right" : "") + "\nset xrange [0.4:" +
                  std::to_string(e.algorithms.size()) + ".6]\n"
                  "set style fill solid 0.35 border\nset style boxplot outliers pointtype 7\n"
                  "set boxwidth 0.5\nset grid ytics lt 1 lc rgb \"#e0e0e0\" lw 1\nunset key\n";
  if (log_y) s += "set logscale y\n";
  // Powers of ten read alike on every axis of the report; over less than a
  // decade they would label every tic 10^4, so gnuplot's numbers stay.
  if (log_y && decades) s += "set format y \"10^{%L}\"\n";
  return s;
}

}  // namespace

std::optional<fs::path> write_ecdf_figure(const fs::path& dir, const Experiment& e,
                                          const std::vector<std::vector<TrialResult>>& results,
                                          std::optional<double> target, const ReportContext& ctx) {
  if (!target) return std::nullopt;
  const long last = last_evaluation(results);
  std::string csv = "label,evaluations,fraction\n", dat;
  bool reached = false;
  for (std::size_t a = 0; a < results.size(); ++a) {
    const std::string& label = e.algorithms[a].label;
    dat += block_header(a, label, "evaluations fraction");
    for (const auto& s : ecdf_steps(results[a], *target, last)) {
      csv += csv_field(label) + "," + std::to_string(s.evaluations) + "," + csv_number(s.fraction) + "\n";
      dat += std::to_string(s.evaluations) + " " + gnuplot::number(s.fraction) + "\n";
      reached = reached || s.fraction > 0;
    }
  }
  write_file_atomic(dir / "ecdf.csv", csv);
  write_file_atomic(dir / "ecdf.dat", dat);
  const std::string text =
      gnuplot::header("ecdf", "fraction of trials that reached the target fitness\n# against "
                              "function evaluations, one step line per algorithm",
                      "ecdf.dat (ecdf.csv as one index block per algorithm: evaluations "
                      "fraction)") +
      ecdf_settings(ctx, *target) + (reached ? "" : nobody_reached(*target)) +
      gnuplot::render_all_terminals("ecdf", ecdf_plot(e));
  return gnuplot::write_script(dir, "ecdf", text);
}

fs::path write_boxplot_figure(const fs::path& dir, const Experiment& e,
                              const std::vector<std::vector<TrialResult>>& results,
                              const ReportContext& ctx) {
  std::string csv = "label,trial,final\n", dat, plot;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (std::size_t a = 0; a < results.size(); ++a) {
    const std::string& label = e.algorithms[a].label;
    for (const auto& r : results[a])
      if (!r.failed())
        csv += csv_field(label) + "," + std::to_string(r.trial) + "," + csv_number(r.best) + "\n";
    dat += block_header(a, label, "final");
    const auto values = finals(results[a]);
    for (double v : values) {
      dat += gnuplot::number(v) + "\n";
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (values.empty()) dat += "NaN\n";  // keeps the block, so index a stays algorithm a
    // gnuplot stops at an empty block, so algorithms without values are left out.
    if (values.empty()) continue;
    plot += std::string(plot.empty() ? "  plot \\\n" : ", \\\n") + "    \"boxplot.dat\" index " +
            std::to_string(a) + " using (" + std::to_string(a + 1) + "):1 with boxplot" +
            colour(a);
  }
  write_file_atomic(dir / "boxplot.csv", csv);
  write_file_atomic(dir / "boxplot.dat", dat);
  std::string text = gnuplot::header("boxplot", "final best fitness of the trials, one box per algorithm",
                                     "boxplot.dat (one index block per algorithm: final)") +
                     boxplot_settings(e, ctx, lo > 0, hi >= 10 * lo);
  if (plot.empty())
    text += "# No algorithm reached a finite fitness: nothing to draw.\n";
  else
    text += gnuplot::render_all_terminals("boxplot", plot + "\n");
  return gnuplot::write_script(dir, "boxplot", text);
}

}  // namespace hystbench
