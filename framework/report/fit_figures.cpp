// The fit figures: their data files (fit_LABEL.csv and the loops' index
// blocks) and the two scripts, fit_LABEL_time.gp and fit_LABEL_loops.gp.
#include "framework/report/fit_figures.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/segment_runs.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/axis_tics.hpp"
#include "framework/report/fit_segment_markers.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {

using figure_script::residual_axis;
using figure_script::segment_markers;
using figure_script::Span;
using figure_script::tic_step;
using figure_script::ytics;

// The measurement is drawn first as a broad light band, the model as a thin
// dark line over it: a good model runs inside the band instead of hiding
// it, and where the two part the band shows on its own.
constexpr const char* kMeasuredStyle = "lw 4 lc rgb \"#b4b4b4\"";
constexpr const char* kModelStyle = "lw 1 lc rgb \"#0072B2\"";
constexpr const char* kResidualColour = "#D55E00";
// More loop panels than this no longer fit a page legibly.
constexpr std::size_t kMaxLoopPanels = 9;
// A time plot of more samples than twice this draws, per bin of samples, the
// range each curve spans (min to max): a fast segment of a long record is
// then its envelope, not a block of ink, and a slow one still a line. About
// half the plot's width in pixels: a segment too fast to draw has at least
// half a period in each bin.
constexpr Eigen::Index kTimeBins = 400;

std::string file_label(const std::string& label) {
  std::string out;
  for (char c : label)
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  return out.empty() ? "algorithm" : out;
}

struct SegmentRuns {
  std::string name;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> runs;  // [begin, end) sample ranges
};

// Segments in order of first appearance; a segment that comes back later
// gets a second run rather than a line joining the two.
std::vector<SegmentRuns> runs_by_segment(const std::vector<std::string>& segments, Eigen::Index n) {
  if (segments.empty()) return {{"", {{0, n}}}};
  std::vector<SegmentRuns> out;
  for (const SegmentRun& run : segment_runs(segments, n)) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const SegmentRuns& s) { return s.name == run.label; });
    if (it == out.end()) it = out.insert(out.end(), {run.label, {}});
    it->runs.push_back({run.begin, run.end});
  }
  return out;
}

std::string fit_csv(const Eigen::VectorXd& t, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                    const Eigen::VectorXd& yhat, const std::vector<std::string>& segments) {
  std::string out = segments.empty() ? "t,u,y_measured,y_model,residual\n"
                                     : "t,u,y_measured,y_model,residual,segment\n";
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    out += csv_number(t[i]) + "," + csv_number(u[i]) + "," + csv_number(y[i]) + "," +
           csv_number(yhat[i]) + "," + csv_number(y[i] - yhat[i]);
    out += (segments.empty() ? "" : "," + csv_field(segments[i])) + "\n";
  }
  return out;
}

std::string loops_data(const std::vector<SegmentRuns>& segs, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) {
  std::string out;
  for (std::size_t k = 0; k < segs.size(); ++k) {
    out += (k ? "\n\n" : "") + std::string("# index ") + std::to_string(k) + ": " +
           gnuplot::one_line(segs[k].name) + "\n# u y_measured y_model\n";
    for (std::size_t r = 0; r < segs[k].runs.size(); ++r) {
      out += r ? "\n" : "";  // a single blank line breaks the line between runs
      for (Eigen::Index i = segs[k].runs[r].first; i < segs[k].runs[r].second; ++i)
        out += gnuplot::number(u[i]) + " " + gnuplot::number(y[i]) + " " + gnuplot::number(yhat[i]) + "\n";
    }
  }
  return out;
}

struct TimeFigure {
  std::string csv, title, markers;
  std::string output_tics, residual_tics;
  bool envelope = false;  // csv holds the binned ranges (envelope_data)
};

// One row per bin of samples: t of the bin's middle, then min and max of the
// measurement, the model and the residual.
struct BinRanges {
  Eigen::MatrixXd lo, hi;  // one row per bin; columns y, model, residual
  std::vector<int> turns;  // reversals of the model's direction inside the bin
};

BinRanges bin_ranges(const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) {
  const Eigen::Index n = y.size();
  BinRanges r{Eigen::MatrixXd(kTimeBins, 3), Eigen::MatrixXd(kTimeBins, 3), std::vector<int>(kTimeBins, 0)};
  for (Eigen::Index b = 0; b < kTimeBins; ++b) {
    const Eigen::Index begin = b * n / kTimeBins, len = (b + 1) * n / kTimeBins - begin;
    const Eigen::VectorXd res = y.segment(begin, len) - yhat.segment(begin, len);
    r.lo.row(b) << y.segment(begin, len).minCoeff(), yhat.segment(begin, len).minCoeff(), res.minCoeff();
    r.hi.row(b) << y.segment(begin, len).maxCoeff(), yhat.segment(begin, len).maxCoeff(), res.maxCoeff();
    for (Eigen::Index i = std::max<Eigen::Index>(begin, 1); i + 1 < begin + len; ++i)
      r.turns[b] += (yhat[i] - yhat[i - 1]) * (yhat[i + 1] - yhat[i]) < 0;
  }
  return r;
}

// Per bin: t, then min and max of y, model and residual. Where the model
// turns three times or more within a bin and its neighbours (a period
// spans at most two bins), each bin takes its neighbours' range too:
// otherwise bins that hold a peak alternate with bins that miss it and the
// edges zigzag.
std::string envelope_data(const Eigen::VectorXd& t, const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) {
  const BinRanges r = bin_ranges(y, yhat);
  const Eigen::Index n = t.size();
  std::string out = "# t y_min y_max model_min model_max residual_min residual_max\n";
  for (Eigen::Index b = 0; b < kTimeBins; ++b) {
    const Eigen::Index first = std::max<Eigen::Index>(b - 1, 0), last = std::min(b + 1, kTimeBins - 1);
    int turns = 0;
    for (Eigen::Index k = first; k <= last; ++k) turns += r.turns[k];
    const Eigen::Index from = turns >= 3 ? first : b, count = turns >= 3 ? last - first + 1 : 1;
    const Eigen::RowVector3d lo = r.lo.middleRows(from, count).colwise().minCoeff();
    const Eigen::RowVector3d hi = r.hi.middleRows(from, count).colwise().maxCoeff();
    out.append(gnuplot::number(t[(b * n / kTimeBins + (b + 1) * n / kTimeBins - 1) / 2]));
    for (int c = 0; c < 3; ++c)
      out.append(" ").append(gnuplot::number(lo[c])).append(" ").append(gnuplot::number(hi[c]));
    out.append("\n");
  }
  return out;
}

// The plot commands of the two panels: lines of the samples, or the edges
// of each curve's envelope with the measured one and the residual filled.
std::pair<std::string, std::string> time_plots(const TimeFigure& f) {
  const std::string model = std::string(" with lines ") + kModelStyle;
  const std::string measured = std::string(" with lines ") + kMeasuredStyle;
  const std::string residual = std::string(" with lines lw 1 lc rgb \"") + kResidualColour + "\"";
  if (!f.envelope) {
    const std::string data = gnuplot::quoted(f.csv) + " skip 1 using 1:";
    return {"  plot " + data + "3" + measured + " title \"measured\", \\\n       " + data + "4" + model +
                " title \"model\"\n",
            "  plot " + data + "5" + residual + " notitle\n"};
  }
  const std::string data = gnuplot::quoted(f.csv) + " using 1:";
  return {"  plot " + data + "2:3 with filledcurves fc rgb \"#b4b4b4\" notitle, \\\n       " + data + "2" +
              measured + " title \"measured (range per bin)\", \\\n       " + data + "3" + measured +
              " notitle, \\\n       " + data + "4" + model + " title \"model\", \\\n       " + data + "5" +
              model + " notitle\n",
          "  plot " + data + "6:7 with filledcurves fc rgb \"" + kResidualColour + "\" notitle, \\\n       " +
              data + "6" + residual + " notitle, \\\n       " + data + "7" + residual + " notitle\n"};
}

// Two panels sharing the time axis; margins in character units keep the
// axes aligned and the labels inside the page at every font size.
std::string time_body(const TimeFigure& f) {
  const auto [top, bottom] = time_plots(f);
  return std::string(f.envelope ? "  set datafile separator whitespace\n" : "  set datafile separator comma\n") +
         "  set multiplot\n"
         "  set yrange [*:*]\n  set autoscale fix\n  set lmargin 10\n  set rmargin 2\n"
         "  set origin 0, 0.38\n  set size 1, 0.62\n  set tmargin 4\n  set bmargin 0.5\n"
         "  set title " + f.title + " noenhanced offset 0, 1.2\n" + f.markers +
         "  set format x \"\"\n  unset xlabel\n  set ylabel output_label\n" +
         f.output_tics +
         "  set key at graph 1, graph 1.01 right bottom horizontal samplen 2.5\n" +
         top +
         "  unset label\n  unset title\n  unset key\n"
         "  set origin 0, 0\n  set size 1, 0.38\n  set tmargin 0.5\n  set bmargin 3.2\n"
         "  set format x \"% h\"\n  set xlabel \"Time t [s]\"\n"
         "  set ylabel residual_label\n" +
         f.residual_tics + bottom + "  unset multiplot\n  unset arrow\n";
}

TimeFigure time_figure(const std::string& stem, const std::string& who, const Eigen::VectorXd& t,
                       const Eigen::VectorXd& y, const Eigen::VectorXd& yhat,
                       const std::vector<std::string>& segments) {
  Span output, residual;
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    output.add(y[i]);
    output.add(yhat[i]);
    residual.add(y[i] - yhat[i]);
  }
  const bool envelope = t.size() > 2 * kTimeBins;
  return {envelope ? stem + "_time.dat" : stem + ".csv", gnuplot::quoted("Best fit of " + who),
          segment_markers(segments, t), ytics(output, 4), residual_axis(residual), envelope};
}

std::string number_array(const char* name, const std::vector<double>& v) {
  std::string out = "array " + std::string(name) + "[" + std::to_string(v.size()) + "] = [";
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + gnuplot::number(v[k]);
  return out + "]\n";
}

std::string loops_settings(const std::vector<SegmentRuns>& segs, std::size_t shown,
                           const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                           const Eigen::VectorXd& yhat) {
  const std::size_t cols = shown <= 3 ? shown : (shown <= 4 ? 2 : 3);
  const std::size_t rows = (shown + cols - 1) / cols;
  std::string names;
  std::vector<double> xstep, ystep;
  for (std::size_t k = 0; k < shown; ++k) {
    names += (k ? ", " : "") + gnuplot::quoted(segs[k].name);
    Span su, sy;
    for (const auto& [begin, end] : segs[k].runs)
      for (Eigen::Index i = begin; i < end; ++i) su.add(u[i]), sy.add(y[i]), sy.add(yhat[i]);
    // Narrow and short panels leave room for fewer tic labels.
    xstep.push_back(tic_step(su, cols < 3 ? 4 : 1.5));
    ystep.push_back(tic_step(sy, rows < 2 ? 4 : 3));
  }
  return "# One panel per segment: the first `panels` index blocks of the data\n"
         "# file, with tic spacing per panel (0: gnuplot's choice).\npanels = " +
         std::to_string(shown) + "\nrows = " + std::to_string(rows) + "\ncols = " +
         std::to_string(cols) + "\narray segment[" + std::to_string(shown) + "] = [" + names +
         "]\n" + number_array("xstep", xstep) + number_array("ystep", ystep) +
         "set grid lt 1 lc rgb \"#e0e0e0\" lw 1\n"
         "# Segment names stay readable where a loop runs under them.\n"
         "set style textbox opaque noborder\n"
         "# Tight axes plus a small margin, so no loop touches the frame.\n"
         "set autoscale fix\nset offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06\n";
}

// Margins in character units, so the panels keep their room at every
// font size; the segment name sits inside the panel's upper left corner,
// which a loop rising to the right leaves free.
std::string loops_body(const std::string& dat, const std::string& title) {
  const std::string data = gnuplot::quoted(dat) + " index i-1 using 1:";
  return "  set multiplot layout rows, cols title " + title + " noenhanced \\\n"
         "      margins char 9, char 2, char 3.5, char 3.5 spacing char 7, char 2\n"
         "  do for [i=1:panels] {\n"
         "    set label 1 segment[i] at graph 0.04, graph 0.9 left front boxed noenhanced\n"
         "    set xlabel (i > panels - cols ? input_label : \"\")\n"
         "    set ylabel ((i - 1) % cols == 0 ? output_label : \"\")\n"
         "    if (xstep[i] > 0) { set xtics xstep[i] } else { set xtics autofreq }\n"
         "    if (ystep[i] > 0) { set ytics ystep[i] } else { set ytics autofreq }\n"
         "    # One key for all panels, in one row above the first.\n"
         "    if (i == 1) { set key at screen 0.98, graph 1.02 right bottom vertical maxrows 1 \\\n"
         "                  samplen 2.5 } else { unset key }\n"
         "    # Measured first, as a broad light band; the model thin on top of it.\n"
         "    plot " + data + "2 with lines " + kMeasuredStyle + " title \"measured\", \\\n         " +
         data + "3 with lines " + kModelStyle + " title \"model\"\n  }\n  unset multiplot\n"
         "  unset label\n";
}

// Axis titles as variables at the top of the script, easy to restyle.
std::string axis_labels(const ReportContext& ctx) {
  const auto with_unit = [](std::string text, const std::string& unit) {
    return unit.empty() ? text : text + " [" + unit + "]";
  };
  return "input_label = " + gnuplot::quoted(with_unit("Input u", ctx.input_unit)) +
         "\noutput_label = " + gnuplot::quoted(with_unit("Output y", ctx.output_unit)) +
         // on two lines: the residual panel is short
         "\nresidual_label = \"Residual\\n\" . " + gnuplot::quoted(with_unit("y − ŷ", ctx.output_unit)) + "\n";
}

fs::path time_script(const fs::path& dir, const std::string& stem, const std::string& who,
                     const std::string& axes,
                     const Eigen::VectorXd& t, const Eigen::VectorXd& y,
                     const Eigen::VectorXd& yhat, const std::vector<std::string>& segments) {
  const std::string name = stem + "_time";
  const TimeFigure f = time_figure(stem, who, t, y, yhat, segments);
  if (f.envelope) write_file_atomic(dir / f.csv, envelope_data(t, y, yhat));
  return gnuplot::write_script(
      dir, name,
      gnuplot::header(name, "measured and model output over time (top), residual (bottom)",
                      f.envelope ? f.csv + " (" + std::to_string(kTimeBins) +
                                       " bins of samples: t, then min and max of y, model, residual)"
                                 : stem + ".csv (t,u,y_measured,y_model,residual[,segment])") +
          axes + gnuplot::render_all_terminals(name, time_body(f), true));
}

fs::path loops_script(const fs::path& dir, const std::string& stem, const std::string& who,
                      const std::string& axes,
                      const std::vector<SegmentRuns>& segs, const Eigen::VectorXd& u,
                      const Eigen::VectorXd& y, const Eigen::VectorXd& yhat) {
  const std::string name = stem + "_loops";
  const std::size_t shown = std::min(segs.size(), kMaxLoopPanels);
  std::string title = "Best fit of " + who + ": u–y loops";
  if (shown < segs.size())
    title += " (first " + std::to_string(shown) + " of " + std::to_string(segs.size()) +
             " segments)";
  return gnuplot::write_script(
      dir, name,
      gnuplot::header(name, "input-output (u-y) loops, measured and model",
                    name + ".dat (one index block per segment: u y_measured y_model)") +
          axes + loops_settings(segs, shown, u, y, yhat) +
          gnuplot::render_all_terminals(name, loops_body(name + ".dat", gnuplot::quoted(title)),
                                        true));
}

void check_sizes(const Eigen::VectorXd& t, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                 const Eigen::VectorXd& yhat, const std::vector<std::string>& segments) {
  const auto n = t.size();
  if (u.size() != n || y.size() != n || yhat.size() != n ||
      (!segments.empty() && Eigen::Index(segments.size()) != n))
    throw std::invalid_argument("write_fit_figures: t, u, y_measured, y_model and segments "
                                "(when given) must have the same length");
}

}  // namespace

std::vector<fs::path> write_fit_figures(const fs::path& dir, const std::string& label,
                                        const Eigen::VectorXd& t, const Eigen::VectorXd& u,
                                        const Eigen::VectorXd& y_measured,
                                        const Eigen::VectorXd& y_model,
                                        const std::vector<std::string>& segments,
                                        const ReportContext& ctx) {
  check_sizes(t, u, y_measured, y_model, segments);
  const std::string stem = "fit_" + file_label(label);
  const auto segs = runs_by_segment(segments, t.size());
  write_file_atomic(dir / (stem + ".csv"), fit_csv(t, u, y_measured, y_model, segments));
  write_file_atomic(dir / (stem + "_loops.dat"), loops_data(segs, u, y_measured, y_model));
  const std::string who = label + " on " + ctx.problem;
  const std::string axes = axis_labels(ctx);
  return {time_script(dir, stem, who, axes, t, y_measured, y_model, segments),
          loops_script(dir, stem, who, axes, segs, u, y_measured, y_model)};
}

}  // namespace hystbench
