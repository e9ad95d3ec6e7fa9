#include "framework/svr/svr_figures.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/figure_style.hpp"
#include "framework/report/axis_tics.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

std::string axis(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " (" + unit + ")";
}

// u, measured, SVR [, grey-box] over the scored part, at most ~4000 points.
std::string loop_csv(const SvrTestRow& row) {
  const bool greybox = row.y_greybox.size() > 0;
  std::string out = std::string("u,measured,svr") + (greybox ? ",greybox" : "") + "\n";
  const Eigen::Index n = row.y.size() - row.scored_from;
  const Eigen::Index step = std::max<Eigen::Index>(1, n / 4000);
  for (Eigen::Index k = row.scored_from; k < row.y.size(); k += step) {
    out += figure_number(row.u[k]) + "," + figure_number(row.y[k]) + "," + figure_number(row.y_svr[k]);
    if (greybox) out += "," + figure_number(row.y_greybox[k]);
    out += "\n";
  }
  return out;
}

std::string loop_tics(const SvrTestRow& row) {
  figure_script::Span u, y;
  for (Eigen::Index k = row.scored_from; k < row.y.size(); ++k) {
    u.add(row.u[k]);
    for (double v : {row.y[k], row.y_svr[k]}) y.add(v);
  }
  return figure_script::xy_tics(u, y);
}

fs::path loop_figure(const fs::path& dir, const SvrExperiment& x, const SvrTestRow& row) {
  const std::string name = "loop_" + table::label_key(row.signal->label);
  write_file_atomic(dir / (name + ".csv"), loop_csv(row));
  std::string plot = "  plot \"" + name + ".csv\" using 1:2 with lines lw 2 lc rgb \"black\" title \"measured\", \\\n"
                     "       \"" + name + ".csv\" using 1:3 with lines lw 1.5 dt 2 lc rgb \"#d62728\" title \"SVR\"";
  if (row.y_greybox.size() > 0)
    plot += ", \\\n       \"" + name + ".csv\" using 1:4 with lines lw 1.5 dt 4 lc rgb \"#1f77b4\" title \"grey-box\"";
  const std::string text =
      gnuplot::header(name, "hysteresis loop at " + row.signal->label + ": measured and modelled output against the input",
                      name + ".csv") +
      "set datafile separator \",\"\n" + gnuplot::key_above_plot() + "set grid\n" +
      "set title " + gnuplot::quoted(row.signal->label) + " noenhanced\n" +
      "set xlabel " + gnuplot::quoted(axis("input", x.u_unit)) + " noenhanced\n" +
      "set ylabel " + gnuplot::quoted(axis("output", x.y_unit)) + " noenhanced\n" + loop_tics(row) +
      gnuplot::render_all_terminals(name, plot + "\n");
  return gnuplot::write_script(dir, name, text);
}

std::string error_csv(const SvrResults& r) {
  std::string out = "index,signal,svr_re_percent,greybox_re_percent\n";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const SvrTestRow& row = r.rows[i];
    out += std::to_string(i) + "," + csv_field(row.signal->label) + "," + figure_number(100.0 * row.svr.re) + "," +
           (row.greybox ? figure_number(100.0 * row.greybox->re) : "") + "\n";
  }
  return out;
}

// The signal names, turned 45°, span about 0.7 of their length each; wider
// side by side than the plot, the figure takes the double column.
bool many_signals(const SvrResults& r) {
  double characters = 0;
  for (const SvrTestRow& row : r.rows) characters += 0.7 * double(row.signal->label.size());  // turned 45°
  return characters > gnuplot::characters_across();
}

fs::path error_figure(const fs::path& dir, const SvrExperiment& x, const SvrResults& r) {
  write_file_atomic(dir / "relative_error.csv", error_csv(r));
  std::string plot = "  plot \"relative_error.csv\" using 1:3:xtic(2) with linespoints lw 1.5 pt 7 lc rgb \"#d62728\" title \"SVR\"";
  if (x.greybox)
    plot += ", \\\n       \"relative_error.csv\" using 1:4 with linespoints lw 1.5 pt 5 lc rgb \"#1f77b4\" title \"grey-box\"";
  const std::string text = gnuplot::header("relative_error", "free-run relative error RE of each model by test signal",
                                           "relative_error.csv") +
                           "set datafile separator \",\"\n" + gnuplot::key_above_plot() + "set grid\n" +
                           "set xtics rotate by 45 right noenhanced\nset ylabel \"RE (%)\"\nset logscale y\n" +
                           "set xrange [-0.5:" + gnuplot::number(double(r.rows.size()) - 0.5) + "]\n" +
                           gnuplot::render_all_terminals("relative_error", plot + "\n", many_signals(r));
  return gnuplot::write_script(dir, "relative_error", text);
}

}  // namespace

std::vector<fs::path> write_svr_figures(const fs::path& dir, const SvrExperiment& x, const SvrResults& r) {
  std::vector<fs::path> scripts{error_figure(dir, x, r)};
  for (const SvrTestRow& row : r.rows) scripts.push_back(loop_figure(dir, x, row));
  return scripts;
}

}  // namespace hystbench
