#include "framework/control/control_figures.hpp"

#include <cmath>
#include <limits>

#include "framework/control/control_metrics.hpp"
#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/model/spectrum.hpp"
#include "framework/report/figure_style.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

struct Curve {
  std::string title;
  const LoopTrace* trace;
};

// The uncontrolled run first, then the compared controllers (not the sweep).
std::vector<Curve> curves(const ControlResults& r) {
  std::vector<Curve> out{{"uncontrolled", &r.uncontrolled.first_trial}};
  for (const auto& c : r.controllers)
    if (!c.entry.in_sweep) out.push_back({c.entry.label, &c.first_trial});
  return out;
}

double at(const std::vector<double>& v, std::size_t n) {
  return n < v.size() ? v[n] : std::numeric_limits<double>::quiet_NaN();
}

// t, then per curve: moving RMS (dB re uncontrolled), step, weight norm.
std::string traces_csv(const std::vector<Curve>& cs, const ControlExperiment& x, int decimate,
                       double reference_rms) {
  std::string out = "t";
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (const char* what : {"rms_db", "step", "weight_norm"})
      out.append(",").append(csv_field(cs[i].title + " " + what));
  out += "\n";
  std::vector<std::vector<double>> rms;
  for (const auto& c : cs) rms.push_back(moving_rms(c.trace->true_error, std::lround(x.loop.sample_rate_hz)));
  for (long n = decimate - 1; n < x.loop.samples(); n += decimate) {
    out += figure_number(double(n) / x.loop.sample_rate_hz);
    for (std::size_t i = 0; i < cs.size(); ++i) {
      out.append(",").append(figure_number(20.0 * std::log10(at(rms[i], n) / reference_rms)));
      out.append(",").append(figure_number(at(cs[i].trace->step, n)));
      out.append(",").append(figure_number(at(cs[i].trace->weight_norm, n)));
    }
    out += "\n";
  }
  return out;
}

std::string spectrum_csv(const std::vector<Curve>& cs, const ControlExperiment& x) {
  const long steady = x.windows.steady_samples();
  std::vector<Spectrum> spectra;
  for (const auto& c : cs) {
    if (c.trace->diverged()) {  // stopped early: no steady window to analyse
      spectra.push_back({});
      continue;
    }
    const auto& e = c.trace->true_error;  // beneath the sensor noise
    const long n = std::min<long>(steady, long(e.size()));
    const Eigen::VectorXd tail = Eigen::Map<const Eigen::VectorXd>(e.data() + e.size() - n, n);
    spectra.push_back(welch_spectrum(tail, 1.0 / x.loop.sample_rate_hz, 2048));
  }
  std::string out = "frequency_hz";
  for (const auto& c : cs) out.append(",").append(csv_field(c.title + " power_db"));
  out += "\n";
  // The uncontrolled run never stops early, so its grid is the full one.
  for (std::size_t k = 0; k < spectra[0].frequency.size(); ++k) {
    out += figure_number(spectra[0].frequency[k]);
    for (const auto& s : spectra)
      out.append(",").append(figure_number(k < s.power.size() ? 10.0 * std::log10(s.power[k]) : NAN));
    out += "\n";
  }
  return out;
}

// One line per curve from `file`, y in column first_column + stride * i;
// curve i keeps its colour in every figure (dashed after the eighth).
std::string plot_lines(const std::vector<Curve>& cs, const std::string& file, int first_column,
                       int stride, std::size_t from = 0) {
  std::string plot = "  plot ";
  for (std::size_t i = from; i < cs.size(); ++i) {
    if (i > from) plot += ", \\\n       ";
    plot += "\"" + file + "\" using 1:" + std::to_string(first_column + stride * int(i)) +
            " with lines lw 1.5 lt " + std::to_string(i % 8 + 1) + " dt " + std::to_string(i / 8 + 1) +
            " title " + gnuplot::quoted(cs[i].title) + " noenhanced";
  }
  return plot + "\n";
}

// Every figure names every controller in its key: a long list of names
// takes the double column.
bool wide(const std::vector<Curve>& cs) {
  std::vector<std::string> titles;
  for (const auto& c : cs) titles.push_back(c.title);
  return gnuplot::key_needs_double_column(titles);
}

fs::path script(const fs::path& dir, const std::string& name, const std::string& shows,
                const std::string& reads, const std::string& settings, const std::string& plot,
                bool double_column) {
  const std::string text = gnuplot::header(name, shows, reads) +
                           "set datafile separator \",\"\n" + gnuplot::key_above_plot() + "set grid\n" +
                           settings + gnuplot::render_all_terminals(name, plot, double_column);
  return gnuplot::write_script(dir, name, text);
}

}  // namespace

std::vector<fs::path> write_control_figures(const fs::path& dir, const ControlExperiment& x,
                                            const ControlResults& r) {
  const auto cs = curves(r);
  const bool double_column = wide(cs);
  const int decimate = std::max(1, int(std::lround(x.loop.sample_rate_hz / 50.0)));  // 50 points a second
  const double reference = steady_rms(r.uncontrolled.first_trial.true_error, x.windows);
  write_file_atomic(dir / "traces.csv", traces_csv(cs, x, decimate, reference));
  write_file_atomic(dir / "spectrum.csv", spectrum_csv(cs, x));
  const std::string traces = "traces.csv (first noise seed, every " + std::to_string(decimate) +
                             "th sample)";
  return {
      script(dir, "residual_error",
             "1 s moving RMS of the true residual error, dB re the uncontrolled steady level",
             traces, "set xlabel \"time (s)\"\nset ylabel \"residual RMS (dB)\"\n",
             plot_lines(cs, "traces.csv", 2, 3), double_column),
      script(dir, "step_size", "step size mu(n) of every controlled run", traces,
             "set xlabel \"time (s)\"\nset ylabel \"step size\"\nset logscale y\n",
             plot_lines(cs, "traces.csv", 3, 3, 1), double_column),
      script(dir, "weight_norm", "norm of the controller weights |w(n)|", traces,
             "set xlabel \"time (s)\"\nset ylabel \"|w|\"\n", plot_lines(cs, "traces.csv", 4, 3, 1),
             double_column),
      script(dir, "spectrum",
             "Welch spectrum of the true (noise-free) error over the steady window, "
             "uncontrolled and controlled",
             "spectrum.csv", "set xlabel \"frequency (Hz)\"\nset ylabel \"power (dB)\"\nset xrange [0:" +
                                 gnuplot::number(std::min(x.loop.sample_rate_hz / 2, 8 * x.loop.disturbance_hz)) + "]\n",
             plot_lines(cs, "spectrum.csv", 2, 1), double_column),
  };
}

}  // namespace hystbench
