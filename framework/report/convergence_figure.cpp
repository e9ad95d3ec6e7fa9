// The convergence figure: its data file of gnuplot index blocks, the axis
// and key settings, and the plot of median lines and quartile bands.
#include "framework/report/convergence_figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {


// Okabe–Ito colours: distinguishable with the common colour-vision
// deficiencies and still distinct when printed in grey.
constexpr std::array<const char*, 7> kPalette{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                              "#E69F00", "#56B4E9", "#000000"};

bool has_finite_median(const ConvergenceCurve& c) {
  return std::any_of(c.median.begin(), c.median.end(), [](double m) { return std::isfinite(m); });
}

// gnuplot index blocks: per curve, the rows with a finite median (the
// line) and then, when there are any, the rows with a finite upper quartile
// (the band; filledcurves draws nonsense through undefined points).
struct ConvergenceData {
  std::string text;
  std::vector<int> line_block, band_block;  // per curve; band -1 when empty
};

int add_block(ConvergenceData& d, const std::string& title, const std::string& rows) {
  const int index = int(d.line_block.size() + d.band_block.size());
  d.text += (index ? "\n\n" : "") + std::string("# index ") + std::to_string(index) + ": " +
            gnuplot::one_line(title) + "\n# evaluations q25 median q75\n" + rows;
  return index;
}

ConvergenceData convergence_data(const std::vector<const ConvergenceCurve*>& curves) {
  ConvergenceData d;
  for (const auto* c : curves) {
    std::string line, band;
    for (std::size_t i = 0; i < c->evaluations.size(); ++i) {
      if (!std::isfinite(c->median[i])) continue;
      const std::string row = std::to_string(c->evaluations[i]) + " " + gnuplot::number(c->q25[i]) + " " +
                              gnuplot::number(c->median[i]) + " " + gnuplot::number(c->q75[i]) + "\n";
      line += row;
      if (std::isfinite(c->q75[i])) band += row;
    }
    d.line_block.push_back(add_block(d, c->label + " (median line)", line));
    d.band_block.push_back(band.empty() ? -1 : add_block(d, c->label + " (quartile band)", band));
  }
  return d;
}

// Decade labels read best, but a range narrower than a decade would have
// none, so gnuplot's own labels are kept there.
bool spans_a_decade(const std::vector<const ConvergenceCurve*>& curves, double floor) {
  double lo = floor > 0 ? floor : std::numeric_limits<double>::infinity();
  double hi = floor;
  for (const auto* c : curves)
    for (std::size_t i = 0; i < c->median.size(); ++i) {
      if (std::isfinite(c->q25[i]) && c->q25[i] > 0) lo = std::min(lo, c->q25[i]);
      if (std::isfinite(c->q75[i])) hi = std::max(hi, c->q75[i]);
      if (std::isfinite(c->median[i])) hi = std::max(hi, c->median[i]);
    }
  return hi >= 10.0 * lo;
}

// The noise floor is the best any fit can do, so it is drawn as the line
// the curves approach; a log axis cannot show a floor of zero.
double drawable_floor(const ReportContext& ctx) {
  const double floor = ctx.noise_floor.value_or(0.0);
  return std::isfinite(floor) && floor > 0 ? floor : 0.0;
}

std::string convergence_plot(const std::vector<const ConvergenceCurve*>& curves,
                             const ConvergenceData& data, double floor) {
  std::string plot = "  plot \\\n";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::string colour = std::string(" lc rgb \"") + kPalette[k % kPalette.size()] + "\"";
    // Past the palette, colours repeat with a new dash pattern.
    const std::string dash = " dt " + std::to_string(1 + k / kPalette.size());
    const auto block = [](int i) { return "    \"convergence.dat\" index " + std::to_string(i); };
    if (data.band_block[k] >= 0)
      plot += block(data.band_block[k]) + " using 1:2:4 with filledcurves" + colour +
              " notitle, \\\n";
    plot += block(data.line_block[k]) + " using 1:3 with lines lw 2" + dash + colour + " title " +
            gnuplot::quoted(curves[k]->label) + " noenhanced";
    plot += k + 1 < curves.size() ? ", \\\n" : "\n";
  }
  if (floor > 0)
    plot.insert(plot.size() - 1, ", \\\n    noise_floor with lines lw 1.5 dt 2 lc rgb \"#404040\" "
                                 "title \"noise floor\"");
  return plot;
}

// Upper end of the fitness axis, so that the whole trace shows: above the
// highest median or upper quartile. Only when the first candidates of a model that can
// diverge reach astronomically large (finite) fitness, more than kDecades
// above the highest median once 1 % of the budget is spent, would that
// flatten every curve against the axis; then the axis stops at 3x that
// median and a label says how high the traces start.
struct FitnessAxisTop {
  double top = 0.0;      // 0: leave the range to gnuplot
  double highest = 0.0;  // the highest median or upper quartile, drawn or not
  bool clipped() const { return top > 0 && highest > top; }
};

FitnessAxisTop fitness_axis_top(const std::vector<const ConvergenceCurve*>& curves) {
  constexpr double kDecades = 4;
  long last = 0;
  for (const auto* c : curves)
    if (!c->evaluations.empty()) last = std::max(last, c->evaluations.back());
  double highest = 0.0, after_start = 0.0;
  for (const auto* c : curves)
    for (std::size_t i = 0; i < c->evaluations.size(); ++i) {
      if (std::isfinite(c->q75[i])) highest = std::max(highest, c->q75[i]);
      if (!std::isfinite(c->median[i])) continue;
      highest = std::max(highest, c->median[i]);
      if (c->evaluations[i] * 100 >= last) after_start = std::max(after_start, c->median[i]);
    }
  if (highest <= 0) return {};
  if (after_start > 0 && highest > after_start * std::pow(10.0, kDecades)) return {3 * after_start, highest};
  return {1.5 * highest, highest};
}

std::string convergence_settings(const std::vector<const ConvergenceCurve*>& curves,
                                 const ReportContext& ctx) {
  const std::string title = "Convergence — " + ctx.experiment + " (" + ctx.problem + ")";
  const std::string subtitle =
      "median and interquartile range over " + std::to_string(ctx.trials) + " trials";
  std::string s = "set title " + gnuplot::quoted(title) + ".\"\\n\"." + gnuplot::quoted(subtitle) +
                  " noenhanced\n"
                  "set xlabel \"Function evaluations\"\nset ylabel " +
                  gnuplot::quoted(ctx.fitness_axis("Best-so-far fitness")) + "\n"
                  "set logscale xy\nset format x \"10^{%L}\"\n"
                  "# The axis ends at the last evaluation rather than the next decade.\n"
                  "set xrange [1:*]\nset autoscale xfixmax\n";
  if (spans_a_decade(curves, drawable_floor(ctx))) s += "set format y \"10^{%L}\"\n";
  if (drawable_floor(ctx) > 0)
    s += "noise_floor = " + gnuplot::number(drawable_floor(ctx)) + "  # SSE of the true parameters\n";
  if (const FitnessAxisTop axis = fitness_axis_top(curves); axis.clipped())
    s += "# The first evaluations reach " + gnuplot::number(axis.highest) +
         ": the axis stops at 3x the highest median after 1 % of the budget.\n"
         "set yrange [*:" + gnuplot::number(axis.top) + "]\n"
         "set label 1 " + gnuplot::quoted("traces start above the axis, up to " + format_number("%.3g", axis.highest)) +
         " at graph 0.02, graph 0.96 left front noenhanced\n";
  else if (axis.top > 0)
    s += "# The whole trace: the axis ends above the highest upper quartile.\n"
         "set yrange [*:" + gnuplot::number(axis.top) + "]\n";
  return s + "set grid xtics ytics lt 1 lc rgb \"#e0e0e0\" lw 1\n" + gnuplot::key_above_plot() +
         "set style fill transparent solid 0.25 noborder\n";
}

}  // namespace

fs::path write_convergence_figure(const fs::path& dir, const std::vector<ConvergenceCurve>& curves,
                                  const ReportContext& ctx) {
  std::vector<const ConvergenceCurve*> plotted;
  for (const auto& c : curves)
    if (has_finite_median(c)) plotted.push_back(&c);
  const ConvergenceData data = convergence_data(plotted);
  write_file_atomic(dir / "convergence.dat", data.text);
  std::string text = gnuplot::header(
      "convergence",
      "best-so-far fitness against function evaluations, one median\n# line and one "
      "interquartile band per algorithm",
      "convergence.dat (the finite rows of convergence.csv; per algorithm\n# one index block "
      "for the median line and one for the band: evaluations q25 median q75)");
  text += convergence_settings(plotted, ctx);
  if (plotted.empty())
    text += "# No algorithm reached a finite fitness: nothing to draw.\n";
  else
    text += gnuplot::render_all_terminals("convergence",
                                 convergence_plot(plotted, data, drawable_floor(ctx)));
  return gnuplot::write_script(dir, "convergence", text);
}

}  // namespace hystbench
