#include "framework/discovery/comparison_figures.hpp"

#include <algorithm>
#include <cmath>

#include "framework/io/segment_runs.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/figure_style.hpp"
#include "framework/report/axis_tics.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace gp = gnuplot;
namespace {

// Okabe–Ito colours, as in the other hystbench figures.
constexpr const char* kEstimationColour = "#0072B2";
constexpr const char* kHeldoutColour = "#D55E00";
constexpr const char* kMixedColour = "#707070";
constexpr const char* kResidualColour = "#D55E00";
// More named boundaries than this crowd the strip above the residual.
constexpr std::size_t kMaxNamedRuns = 12;
// More shaded spans than this (e.g. every other sample held out) would
// hide the residual; they are left out with a comment in the script.
constexpr std::size_t kMaxShadedSpans = 200;

std::string with_unit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " [" + unit + "]";
}

// gnuplot data files take double-quoted strings; a quote inside becomes '.
std::string data_string(std::string s) {
  std::replace(s.begin(), s.end(), '"', '\'');
  std::replace_if(
      s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return "\"" + s + "\"";
}

// ---- residual over time ----------------------------------------------------

std::vector<std::pair<double, double>> heldout_spans(const ComparisonInput& in) {
  std::vector<std::pair<double, double>> spans;
  const Eigen::Index n = in.estimation.size();
  for (Eigen::Index i = 0; i < n;) {
    if (in.estimation[i] != 0) {
      ++i;
      continue;
    }
    Eigen::Index end = i;
    while (end < n && in.estimation[end] == 0) ++end;
    // Half a sample either side, so a span of one sample still shows.
    const double half = 0.5 * (n > 1 ? (in.t[n - 1] - in.t[0]) / double(n - 1) : 0.0);
    spans.push_back({in.t[i] - half, in.t[end - 1] + half});
    i = end;
  }
  return spans;
}

// Whether every segment name fits above its run: inside the frame and clear
// of the name two runs back, which shares its row (names alternate rows).
bool names_fit(const ComparisonInput& in, const std::vector<SegmentRun>& runs) {
  const double t0 = in.t[0], span = in.t[in.t.size() - 1] - t0;
  if (!(span > 0)) return false;
  const double character = 1.0 / gp::characters_across();  // as a share of the width
  std::vector<std::pair<double, double>> extent;             // left and right edge of each name
  for (const auto& run : runs) {
    const double mid = ((in.t[run.begin] + in.t[run.end - 1]) / 2 - t0) / span;
    const double half = 0.5 * character * double(run.label.size());
    extent.push_back({mid - half, mid + half});
    const std::size_t k = extent.size() - 1;
    if (extent[k].first < 0 || extent[k].second > 1 || (k >= 2 && extent[k - 2].second > extent[k].first))
      return false;
  }
  return true;
}

std::string residual_marks(const ComparisonInput& in) {
  std::string out;
  const auto spans = heldout_spans(in);
  if (spans.size() > kMaxShadedSpans) {
    out += "# " + std::to_string(spans.size()) + " held-out spans: too many to shade.\n";
  } else {
    for (const auto& [a, b] : spans)
      out += "set object rect from " + gp::number(a) + ", graph 0 to " + gp::number(b) +
             ", graph 1 behind fc rgb \"#e6e6e6\" fs solid 1.0 noborder\n";
  }
  const auto runs = segment_runs(in.segment, in.t.size());
  const bool named = !in.segment.empty() && runs.size() <= kMaxNamedRuns && names_fit(in, runs);
  for (std::size_t k = 0; k < runs.size() && !in.segment.empty(); ++k) {
    const double begin = in.t[runs[k].begin], end = in.t[runs[k].end - 1];
    if (k > 0)
      out += "set arrow from " + gp::number(begin) + ", graph 0 to " + gp::number(begin) +
             ", graph 1 nohead lc rgb \"#909090\" dt 2 back\n";
    if (named)
      out += "set label " + gp::quoted(runs[k].label) + " at " + gp::number((begin + end) / 2) +
             ", graph " + (k % 2 ? "0.87" : "0.94") + " center front noenhanced font \",9\"\n";
  }
  return out;
}

fs::path residual_figure(const fs::path& dir, const ComparisonInput& in, const Comparison& m,
                         const std::string& title) {
  std::string data = "# t residual\n";
  figure_script::Span span;
  for (Eigen::Index i = 0; i < in.t.size(); ++i) {
    data += gp::number(in.t[i]) + " " + gp::number(in.y[i] - in.y_model[i]) + "\n";
    span.add(in.y[i] - in.y_model[i]);
  }
  write_file_atomic(dir / "residual.dat", data);
  const double sigma = m.noise_floor.sigma;
  const bool has_heldout = m.parts.heldout.has_value();
  std::string body = "  plot \"residual.dat\" using 1:2 with lines lw 1 lc rgb \"" +
                     std::string(kResidualColour) + "\" title \"residual y − ŷ\"";
  if (std::isfinite(sigma) && sigma > 0)
    body +=
        ", \\\n       sigma with lines dt 3 lw 1.5 lc rgb \"#000000\" title \"± noise σ\", \\\n"
        "       -sigma with lines dt 3 lw 1.5 lc rgb \"#000000\" notitle";
  if (has_heldout)
    body += ", \\\n       NaN with boxes fs solid 1.0 fc rgb \"#e6e6e6\" title \"held out\"";
  body += "\n";
  const std::string script =
      gp::header("residual",
                 "residual over time; held-out spans shaded, segment boundaries "
                 "dashed,\n# noise floor as dotted lines",
                 "residual.dat (t residual)") +
      "residual_label = " + gp::quoted(with_unit("Residual y − ŷ", in.y_unit)) + "\n" +
      "sigma = " + gp::number(sigma) + "  # noise floor estimate\n" + "set title " +
      gp::quoted("Residual — " + title) +
      " noenhanced\n"
      "set xlabel \"Time t [s]\"\nset ylabel residual_label\n"
      "set grid lt 1 lc rgb \"#e0e0e0\" lw 1\nset autoscale xfix\n"
      "# Room above the data for the segment names; the key sits above the frame.\n"
      "set offsets 0, 0, graph 0.2, graph 0.05\n" +
      gp::key_above_plot() +
      figure_script::ytics(span, 4) + residual_marks(in) + gp::render_all_terminals("residual", body);
  return gp::write_script(dir, "residual", script);
}

// ---- RMSE per segment --------------------------------------------------------

const char* part_colour(const std::string& part) {
  return part == "heldout" ? kHeldoutColour : part == "mixed" ? kMixedColour : kEstimationColour;
}

// The width of the bars' names side by side, with a space between two.
double label_characters(const std::vector<SegmentErrors>& segs) {
  double sum = 0;
  for (const auto& seg : segs) sum += double(seg.segment.size()) + 2;
  return sum;
}

fs::path segment_figure(const fs::path& dir, const ComparisonInput& in, const Comparison& m,
                        const std::string& title) {
  const auto& segs = m.by_segment;
  std::string data = "# index segment rmse part\n";
  bool seen[3] = {false, false, false};
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const std::string& part = segs[k].part;
    seen[part == "estimation" ? 0 : part == "heldout" ? 1 : 2] = true;
    data += std::to_string(k) + " " + data_string(segs[k].segment) + " " +
            gp::number(segs[k].metrics.rmse) + " " + part + "\n";
  }
  if (segs.empty())
    data += "0 \"all\" " + gp::number(m.parts.all.rmse) + " estimation\n";
  // The axis from 0 holds every bar and the noise-floor line.
  figure_script::Span span;
  for (double v : {0.0, m.noise_floor.sigma, segs.empty() ? m.parts.all.rmse : 0.0}) span.add(v);
  for (const auto& seg : segs) span.add(seg.metrics.rmse);
  write_file_atomic(dir / "segment_rmse.dat", data);
  const std::size_t bars = std::max<std::size_t>(1, segs.size());
  const double sigma = m.noise_floor.sigma;
  std::string body = "  plot ";
  const char* parts[] = {"estimation", "heldout", "mixed"};
  const char* names[] = {estimation_name(in), "held out", "mixed"};
  bool first = true;
  for (int p = 0; p < 3; ++p) {
    if (!seen[p] && !(p == 0 && segs.empty())) continue;
    body += std::string(first ? "" : ", \\\n       ") +
            "\"segment_rmse.dat\" using 1:(strcol(4) eq \"" + parts[p] +
            "\" ? $3 : NaN):xtic(2) with boxes fc rgb \"" + part_colour(parts[p]) + "\" title \"" +
            names[p] + "\"";
    first = false;
  }
  if (std::isfinite(sigma) && sigma > 0)
    body += ", \\\n       sigma with lines dt 2 lw 2 lc rgb \"#000000\" title \"noise σ\"";
  body += "\n";
  const std::string script =
      gp::header("segment_rmse",
                 "RMSE per segment (bars; colour: estimation / held out / mixed)"
                 ",\n# noise floor as a dashed line",
                 "segment_rmse.dat (index segment rmse part)") +
      "rmse_label = " + gp::quoted(with_unit("RMSE", in.y_unit)) + "\n" +
      "sigma = " + gp::number(sigma) + "  # noise floor estimate\n" + "set title " +
      gp::quoted("Error per segment — " + title) +
      " noenhanced\n"
      "set ylabel rmse_label\nset yrange [0:" + gp::number(1.08 * span.hi) + "]\n"
      "set xrange [-0.6:" +
      gp::number(double(bars) - 0.4) +
      "]\n"
      "set style fill solid 0.85 border rgb \"#404040\"\nset boxwidth 0.7\n"
      "# Many segments: names upright, ending at their bar, so none leaves the page.\n"
      "set xtics nomirror noenhanced" +
      (label_characters(segs) > gp::characters_across() ? " rotate by 90 right" : "") +
      "\n"
      "set grid ytics lt 1 lc rgb \"#e0e0e0\" lw 1\n" +
      gp::key_above_plot() +
      figure_script::ytics(span, 4) + gp::render_all_terminals("segment_rmse", body);
  return gp::write_script(dir, "segment_rmse", script);
}

// ---- correlations --------------------------------------------------------------

double plot_limit(const Correlation& c) {
  double m = c.bound;
  for (double v : c.values)
    if (std::isfinite(v)) m = std::max(m, std::abs(v));
  return std::isfinite(m) && m > 0 ? std::min(1.0, 1.15 * m) : 1.0;
}

std::string correlation_block(const Correlation& c, const std::string& what) {
  std::string out = "# " + what + ": lag value\n";
  for (std::size_t i = 0; i < c.lags.size(); ++i)
    out += std::to_string(c.lags[i]) + " " + gp::number(c.values[i]) + "\n";
  return out;
}

std::string correlation_panel(const std::string& title, int index, const std::string& bound_var,
                              double limit, const std::string& xrange) {
  return "  set title " + gp::quoted(title) + "\n  set yrange [" + gp::number(-limit) + ":" +
         gp::number(limit) + "]\n  set xrange " + xrange + "\n  plot \"correlation.dat\" index " +
         std::to_string(index) +
         " using 1:2 with impulses lw 3 lc rgb \"#0072B2\" notitle, \\\n"
         "       \"\" index " +
         std::to_string(index) +
         " using 1:2 with points pt 7 ps 0.5 lc rgb \"#0072B2\" notitle, \\\n       " + bound_var +
         " with lines dt 2 lw 1.5 lc rgb \"#D55E00\" title \"99 % band\", \\\n       -" +
         bound_var +
         " with lines dt 2 lw 1.5 lc rgb \"#D55E00\" notitle, \\\n"
         "       0 with lines lw 1 lc rgb \"#404040\" notitle\n";
}

fs::path correlation_figure(const fs::path& dir, const Comparison& m,
                            const std::string& title) {
  const Correlation& acf = m.residual.acf;
  const Correlation& ccf = m.residual.ccf;
  write_file_atomic(dir / "correlation.dat",
                    correlation_block(acf, "index 0: residual autocorrelation") + "\n\n" +
                        correlation_block(ccf, "index 1: input-residual cross-correlation"));
  const int lags = int(acf.lags.size());
  const std::string body =
      "  set multiplot layout 2, 1 title " + gp::quoted("Residual tests — " + title) +
      " noenhanced\n" +
      correlation_panel("Autocorrelation of the residual r_{ee}(τ)", 0, "acf_bound",
                        plot_limit(acf), "[0.5:" + std::to_string(lags) + ".5]") +
      "  set xlabel \"Lag τ [samples]  (τ > 0: residual against past input)\"\n" +
      correlation_panel("Cross-correlation of input and residual r_{ue}(τ)", 1, "ccf_bound",
                        plot_limit(ccf),
                        "[-" + std::to_string(lags) + ".5:" + std::to_string(lags) + ".5]") +
      "  unset xlabel\n  unset multiplot\n";
  const std::string script =
      gp::header("correlation",
                 "residual autocorrelation (top) and input-residual "
                 "cross-correlation\n# (bottom) with the 99 % band ±2.58/√N",
                 "correlation.dat (index 0: ACF, index 1: CCF; lag value)") +
      "acf_bound = " + gp::number(acf.bound) + "\n" +
      "ccf_bound = " + gp::number(ccf.bound) + "\n" +
      "set grid lt 1 lc rgb \"#e0e0e0\" lw 1\n" + gp::key_above_plot() +
      "set ylabel \"Correlation\"\nset xtics 5\nset mxtics 5\n" +
      gp::render_all_terminals("correlation", body, true);
  return gp::write_script(dir, "correlation", script);
}

}  // namespace

FigureFiles write_comparison_figures(const fs::path& dir, const ComparisonInput& in,
                                     const Comparison& metrics, const std::string& title) {
  FigureFiles files;
  ReportContext ctx;
  ctx.problem = title;
  ctx.input_unit = in.u_unit;
  ctx.output_unit = in.y_unit;
  files.scripts = write_fit_figures(dir, "model", in.t, in.u, in.y, in.y_model, in.segment, ctx);
  files.data = {dir / "fit_model.csv", dir / "fit_model_loops.dat"};
  files.scripts.push_back(residual_figure(dir, in, metrics, title));
  files.scripts.push_back(segment_figure(dir, in, metrics, title));
  files.scripts.push_back(correlation_figure(dir, metrics, title));
  for (const char* d : {"residual.dat", "segment_rmse.dat", "correlation.dat"})
    files.data.push_back(dir / d);
  return files;
}

}  // namespace hystbench
