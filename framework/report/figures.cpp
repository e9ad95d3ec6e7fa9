#include "framework/report/figures.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench {
namespace fs = std::filesystem;
namespace {

// Okabe–Ito colours: distinguishable with the common colour-vision
// deficiencies and still distinct when printed in grey.
constexpr std::array<const char*, 7> kPalette{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                              "#E69F00", "#56B4E9", "#000000"};
// The measurement is drawn first as a broad light band, the model as a thin
// dark line over it: a good model runs inside the band instead of hiding
// it, and where the two part the band shows on its own.
constexpr const char* kMeasuredStyle = "lw 4 lc rgb \"#b4b4b4\"";
constexpr const char* kModelStyle = "lw 1 lc rgb \"#0072B2\"";
constexpr const char* kResidualColour = "#D55E00";
// More loop panels than this no longer fit a page legibly.
constexpr std::size_t kMaxLoopPanels = 9;
constexpr const char* kImageTypes[] = {".svg", ".png", ".pdf"};

// A double-quoted gnuplot string. Every user-supplied text is also drawn
// `noenhanced`, so '_' or '^' in a label are not read as markup.
std::string gp_string(const std::string& s) { return gnuplot::quoted(s); }

// Labels end up in '#' comment lines of the data files.
std::string one_line(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return s;
}

std::string number(double x) { return gnuplot::number(x); }

std::string file_label(const std::string& label) {
  std::string out;
  for (char c : label)
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  return out.empty() ? "algorithm" : out;
}

std::string script_header(const std::string& name, const std::string& shows,
                          const std::string& reads) {
  return gnuplot::header(name, shows, reads);
}

// The same plot commands run once per output format, so a restyled script
// keeps the three images identical.
std::string render_all_terminals(const std::string& name, const std::string& body) {
  return gnuplot::render_all_terminals(name, body);
}

fs::path write_script(const fs::path& dir, const std::string& name, const std::string& text) {
  return gnuplot::write_script(dir, name, text);
}

// ---- convergence ----------------------------------------------------------

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
            one_line(title) + "\n# evaluations q25 median q75\n" + rows;
  return index;
}

ConvergenceData convergence_data(const std::vector<const ConvergenceCurve*>& curves) {
  ConvergenceData d;
  for (const auto* c : curves) {
    std::string line, band;
    for (std::size_t i = 0; i < c->evaluations.size(); ++i) {
      if (!std::isfinite(c->median[i])) continue;
      const std::string row = std::to_string(c->evaluations[i]) + " " + number(c->q25[i]) + " " +
                              number(c->median[i]) + " " + number(c->q75[i]) + "\n";
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
            gp_string(curves[k]->label) + " noenhanced";
    plot += k + 1 < curves.size() ? ", \\\n" : "\n";
  }
  if (floor > 0)
    plot.insert(plot.size() - 1, ", \\\n    noise_floor with lines lw 1.5 dt 2 lc rgb \"#404040\" "
                                 "title \"noise floor\"");
  return plot;
}

// Upper end of the fitness axis: the highest median once 1 % of the budget
// is spent. The first few candidates of a model that can diverge may have
// astronomically large (finite) fitness; drawn in full they flatten every
// curve against the axis. 0: leave the range to gnuplot.
double fitness_axis_top(const std::vector<const ConvergenceCurve*>& curves) {
  long last = 0;
  for (const auto* c : curves)
    if (!c->evaluations.empty()) last = std::max(last, c->evaluations.back());
  double top = 0.0;
  for (const auto* c : curves)
    for (std::size_t i = 0; i < c->evaluations.size(); ++i)
      if (c->evaluations[i] * 100 >= last && std::isfinite(c->median[i]))
        top = std::max(top, c->median[i]);
  return top;
}

// Many algorithms: the key goes beside the plot, where it covers nothing.
std::string key_placement(std::size_t curves) {
  if (curves > 6) return "set key outside right top opaque spacing 1.1 samplen 2.5\n";
  return "# Curves fall from the upper left, so the lower left stays free.\n"
         "set key bottom left opaque box spacing 1.2 samplen 2.5\n";
}

std::string convergence_settings(const std::vector<const ConvergenceCurve*>& curves,
                                 const ReportContext& ctx) {
  const std::string title = "Convergence — " + ctx.experiment + " (" + ctx.problem + ")";
  const std::string subtitle =
      "median and interquartile range over " + std::to_string(ctx.trials) + " trials";
  std::string s = "set title " + gp_string(title) + ".\"\\n\"." + gp_string(subtitle) +
                  " noenhanced\n"
                  "set xlabel \"Function evaluations\"\nset ylabel " +
                  gp_string(ctx.fitness_axis("Best-so-far fitness")) + "\n"
                  "set logscale xy\nset format x \"10^{%L}\"\n"
                  "# The axis ends at the last evaluation rather than the next decade.\n"
                  "set xrange [1:*]\nset autoscale xfixmax\n";
  if (spans_a_decade(curves, drawable_floor(ctx))) s += "set format y \"10^{%L}\"\n";
  if (drawable_floor(ctx) > 0)
    s += "noise_floor = " + number(drawable_floor(ctx)) + "  # SSE of the true parameters\n";
  if (const double top = fitness_axis_top(curves); top > 0)
    s += "# Fitness axis from the data to 3x the highest median after 1 % of the budget.\n"
         "set yrange [*:" + number(3 * top) + "]\n";
  return s + "set grid xtics ytics lt 1 lc rgb \"#e0e0e0\" lw 1\n" + key_placement(curves.size()) +
         "set style fill transparent solid 0.25 noborder\n";
}

// ---- fit ------------------------------------------------------------------

struct SegmentRuns {
  std::string name;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> runs;  // [begin, end) sample ranges
};

// Segments in order of first appearance; a segment that comes back later
// gets a second run rather than a line joining the two.
std::vector<SegmentRuns> segment_runs(const std::vector<std::string>& segments, Eigen::Index n) {
  std::vector<SegmentRuns> out;
  if (segments.empty()) return {{"", {{0, n}}}};
  for (Eigen::Index i = 0; i < n;) {
    Eigen::Index end = i;
    while (end < n && segments[end] == segments[i]) ++end;
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const SegmentRuns& s) { return s.name == segments[i]; });
    if (it == out.end()) it = out.insert(out.end(), {segments[i], {}});
    it->runs.push_back({i, end});
    i = end;
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
           one_line(segs[k].name) + "\n# u y_measured y_model\n";
    for (std::size_t r = 0; r < segs[k].runs.size(); ++r) {
      out += r ? "\n" : "";  // a single blank line breaks the line between runs
      for (Eigen::Index i = segs[k].runs[r].first; i < segs[k].runs[r].second; ++i)
        out += number(u[i]) + " " + number(y[i]) + " " + number(yhat[i]) + "\n";
    }
  }
  return out;
}

struct Span {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  void add(double x) {
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  }
};

// 1, 2 or 5 times a power of ten, nearest to `intervals` tic intervals:
// gnuplot's own spacing ignores the panel height and crowds short panels.
// 0 (gnuplot's choice) when the data has no width.
double tic_step(const Span& s, double intervals) {
  const double raw = (s.hi - s.lo) / intervals;
  if (!(raw > 0) || !std::isfinite(raw)) return 0.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double best = decade;
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * decade / raw)) < std::abs(std::log(best / raw))) best = m * decade;
  return best;
}

// About `intervals` tic intervals, only over the data, so none is drawn in
// the strip kept free above it.
std::string ytics(const Span& s, double intervals) {
  const double step = tic_step(s, intervals);
  if (step == 0) return "  set ytics autofreq\n";
  const double first = std::ceil(s.lo / step) * step + 0.0;  // + 0.0: no "-0"
  return "  set ytics " + number(first) + ", " + number(step) + ", " + number(s.hi) + "\n";
}

// Symmetric about zero, so a bias of the model shows as an off-centre
// band; three tics fit even the short panel of the PDF.
std::string residual_axis(const Span& s) {
  const double m = std::max(std::abs(s.lo), std::abs(s.hi));
  if (!(m > 0) || !std::isfinite(m)) return "  set yrange [-1:1]\n  set ytics autofreq\n";
  // The largest 1, 2 or 5 times a power of ten that still fits, so the
  // tics at +-step are inside the range.
  const double decade = std::pow(10.0, std::floor(std::log10(m)));
  const double step = m >= 5 * decade ? 5 * decade : (m >= 2 * decade ? 2 * decade : decade);
  return "  set yrange [" + number(-1.08 * m) + ":" + number(1.08 * m) + "]\n  set ytics " +
         number(-step) + ", " + number(step) + ", " + number(step) + "\n";
}

struct TimeSegment {
  std::string name;
  double begin, end;
};

// Contiguous stretches in time order: a name that comes back is a new one.
std::vector<TimeSegment> time_segments(const std::vector<std::string>& segments,
                                       const Eigen::VectorXd& t) {
  std::vector<TimeSegment> out;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (i > 0 && segments[i] == segments[i - 1]) continue;
    const double at = t[Eigen::Index(i)];
    if (!out.empty()) out.back().end = at;
    out.push_back({segments[i], at, at});
  }
  if (!out.empty()) out.back().end = t[t.size() - 1];
  return out;
}

// Whether neighbouring names, centred on their stretches, would overlap in
// the PDF, the most crowded output (10 pt letters up to 7 pt wide across
// about 340 pt of plot).
bool names_collide(const std::vector<TimeSegment>& segs) {
  const double per_char = 7.0 / 340.0 * (segs.back().end - segs.front().begin);
  for (std::size_t k = 1; k < segs.size(); ++k) {
    const double distance = (segs[k].end - segs[k - 1].begin) / 2;  // between the centres
    const auto letters = double(segs[k].name.size() + segs[k - 1].name.size()) / 2 + 1;
    const double needed = letters * per_char;
    if (distance < needed) return true;
  }
  return false;
}

// A dashed line where the segment changes and its name in a strip kept
// free above the data, so a misfit can be traced to its excitation. Names
// that would run into each other alternate between two rows.
std::string segment_markers(const std::vector<std::string>& segments, const Eigen::VectorXd& t) {
  const auto segs = time_segments(segments, t);
  if (segs.empty()) return "  set offsets 0, 0, graph 0.05, graph 0.05\n";
  const bool two_rows = names_collide(segs);
  std::string out = std::string("  set offsets 0, 0, graph ") + (two_rows ? "0.45" : "0.22") +
                    ", graph 0.05\n";
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const std::string begin = number(segs[k].begin);
    if (k > 0)
      out += "  set arrow from " + begin + ", graph 0 to " + begin +
             ", graph 1 nohead lc rgb \"#a0a0a0\" dt 2 back\n";
    out += "  set label " + gp_string(segs[k].name) + " at " +
           number((segs[k].begin + segs[k].end) / 2) + ", graph " +
           (two_rows && k % 2 ? "0.81" : "0.92") + " center noenhanced\n";
  }
  return out;
}

struct TimeFigure {
  std::string csv, title, markers;
  std::string output_tics, residual_tics;
};

// Two panels sharing the time axis; margins in character units keep the
// axes aligned and the labels inside the page at every font size.
std::string time_body(const TimeFigure& f) {
  const std::string data = gp_string(f.csv) + " skip 1 using 1:";
  return "  set datafile separator comma\n  set multiplot\n"
         "  set yrange [*:*]\n  set autoscale fix\n  set lmargin 10\n  set rmargin 2\n"
         "  set origin 0, 0.38\n  set size 1, 0.62\n  set tmargin 4\n  set bmargin 0.5\n"
         "  set title " + f.title + " noenhanced offset 0, 1.2\n" + f.markers +
         "  set format x \"\"\n  unset xlabel\n  set ylabel output_label\n" +
         f.output_tics +
         "  set key at graph 1, graph 1.01 right bottom horizontal samplen 2.5\n"
         "  plot " + data + "3 with lines " + kMeasuredStyle + " title \"measured\", \\\n       " +
         data + "4 with lines " + kModelStyle + " title \"model\"\n"
         "  unset label\n  unset title\n  unset key\n"
         "  set origin 0, 0\n  set size 1, 0.38\n  set tmargin 0.5\n  set bmargin 3.2\n"
         "  set format x \"% h\"\n  set xlabel \"Time t [s]\"\n"
         "  set ylabel residual_label\n" +
         f.residual_tics +
         "  plot " + data + "5 with lines lw 1 lc rgb \"" + kResidualColour +
         "\" notitle\n  unset multiplot\n  unset arrow\n";
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
  return {stem + ".csv", gp_string("Best fit of " + who),
          segment_markers(segments, t), ytics(output, 4), residual_axis(residual)};
}

std::string number_array(const char* name, const std::vector<double>& v) {
  std::string out = "array " + std::string(name) + "[" + std::to_string(v.size()) + "] = [";
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + number(v[k]);
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
    names += (k ? ", " : "") + gp_string(segs[k].name);
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
  const std::string data = gp_string(dat) + " index i-1 using 1:";
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

// ---- rendering ------------------------------------------------------------

bool gnuplot_on_path() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');) {
    const fs::path exe = fs::path(d.empty() ? "." : d) / "gnuplot";
    std::error_code ec;
    if (fs::is_regular_file(exe, ec) && ::access(exe.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The line worth showing from one script's messages (those after byte
// `from` of the log): the first that is not a warning, as gnuplot stops at
// its first error; else the first line.
std::string first_error_line(const fs::path& log, std::uintmax_t from) {
  std::ifstream in(log);
  in.seekg(std::streamoff(from));
  std::string first;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.find("warning:") == std::string::npos) return line;
    if (first.empty()) first = line;
  }
  return first;
}

// Axis titles as variables at the top of the script, easy to restyle.
std::string axis_labels(const ReportContext& ctx) {
  const auto with_unit = [](std::string text, const std::string& unit) {
    return unit.empty() ? text : text + " [" + unit + "]";
  };
  return "input_label = " + gp_string(with_unit("Input u", ctx.input_unit)) +
         "\noutput_label = " + gp_string(with_unit("Output y", ctx.output_unit)) +
         // on two lines: the residual panel is short
         "\nresidual_label = \"Residual\\n\" . " + gp_string(with_unit("y − ŷ", ctx.output_unit)) + "\n";
}

fs::path time_script(const fs::path& dir, const std::string& stem, const std::string& who,
                     const std::string& axes,
                     const Eigen::VectorXd& t, const Eigen::VectorXd& y,
                     const Eigen::VectorXd& yhat, const std::vector<std::string>& segments) {
  const std::string name = stem + "_time";
  return write_script(
      dir, name,
      script_header(name, "measured and model output over time (top), residual (bottom)",
                    stem + ".csv (t,u,y_measured,y_model,residual[,segment])") +
          axes + render_all_terminals(name, time_body(time_figure(stem, who, t, y, yhat, segments))));
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
  return write_script(
      dir, name,
      script_header(name, "input-output (u-y) loops, measured and model",
                    name + ".dat (one index block per segment: u y_measured y_model)") +
          axes + loops_settings(segs, shown, u, y, yhat) +
          render_all_terminals(name, loops_body(name + ".dat", gp_string(title))));
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

fs::path write_convergence_figure(const fs::path& dir, const std::vector<ConvergenceCurve>& curves,
                                  const ReportContext& ctx) {
  std::vector<const ConvergenceCurve*> plotted;
  for (const auto& c : curves)
    if (has_finite_median(c)) plotted.push_back(&c);
  const ConvergenceData data = convergence_data(plotted);
  write_file_atomic(dir / "convergence.dat", data.text);
  std::string text = script_header(
      "convergence",
      "best-so-far fitness against function evaluations, one median\n# line and one "
      "interquartile band per algorithm",
      "convergence.dat (the finite rows of convergence.csv; per algorithm\n# one index block "
      "for the median line and one for the band: evaluations q25 median q75)");
  text += convergence_settings(plotted, ctx);
  if (plotted.empty())
    text += "# No algorithm reached a finite fitness: nothing to draw.\n";
  else
    text += render_all_terminals("convergence",
                                 convergence_plot(plotted, data, drawable_floor(ctx)));
  return write_script(dir, "convergence", text);
}

std::vector<fs::path> write_fit_figures(const fs::path& dir, const std::string& label,
                                        const Eigen::VectorXd& t, const Eigen::VectorXd& u,
                                        const Eigen::VectorXd& y_measured,
                                        const Eigen::VectorXd& y_model,
                                        const std::vector<std::string>& segments,
                                        const ReportContext& ctx) {
  check_sizes(t, u, y_measured, y_model, segments);
  const std::string stem = "fit_" + file_label(label);
  const auto segs = segment_runs(segments, t.size());
  write_file_atomic(dir / (stem + ".csv"), fit_csv(t, u, y_measured, y_model, segments));
  write_file_atomic(dir / (stem + "_loops.dat"), loops_data(segs, u, y_measured, y_model));
  const std::string who = label + " on " + ctx.problem;
  const std::string axes = axis_labels(ctx);
  return {time_script(dir, stem, who, axes, t, y_measured, y_model, segments),
          loops_script(dir, stem, who, axes, segs, u, y_measured, y_model)};
}

std::vector<fs::path> render_figures(const fs::path& dir, const std::vector<fs::path>& scripts,
                                     std::string& note) {
  note.clear();
  std::vector<fs::path> images;
  if (!gnuplot_on_path()) {
    note = "gnuplot not found: install gnuplot (Debian: apt-get install gnuplot-nox), then run "
           "`gnuplot NAME.gp` inside " + dir.string();
    return images;
  }
  const fs::path log = dir / "gnuplot.log";
  std::error_code ec;
  fs::remove(log, ec);
  for (const auto& script : scripts) {
    const fs::path name = script.filename();
    for (const char* ext : kImageTypes)  // so that only fresh images are returned
      fs::remove(dir / fs::path(name).replace_extension(ext), ec);
    const std::uintmax_t log_before = fs::exists(log, ec) ? fs::file_size(log, ec) : 0;
    const std::string command = "cd " + shell_quote(dir.string()) + " && gnuplot " +
                                shell_quote(name.string()) + " 2>> gnuplot.log";
    if (std::system(command.c_str()) != 0 && note.empty())
      note = "gnuplot failed on " + name.string() + ": " + first_error_line(log, log_before) +
             " (see " + log.string() + ")";
    for (const char* ext : kImageTypes) {
      const fs::path image = dir / fs::path(name).replace_extension(ext);
      if (fs::exists(image, ec) && fs::file_size(image, ec) > 0) images.push_back(image);
    }
  }
  if (fs::exists(log, ec) && fs::file_size(log, ec) == 0) fs::remove(log, ec);
  return images;
}

}  // namespace hystbench
