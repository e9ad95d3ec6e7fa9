#include "framework/tracking/tracking_figures.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/axis_tics.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/table_format.hpp"
#include "framework/robust/linear_system.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;
namespace gp = gnuplot;

// The controller the time figures show: the first reduced H∞ one, else the first.
std::size_t shown_controller(const TrackingExperiment& x) {
  for (std::size_t i = 0; i < x.controllers.size(); ++i)
    if (x.controllers[i].kind == TrackingController::Kind::Hinf && x.controllers[i].order == "reduced") return i;
  return 0;
}

// The time figures show at most 0.1 s of the window (one period at least).
Eigen::Index shown_samples(const TrackingRow& row, double dt) {
  const WindowSamples& w = row.run.window;
  return std::min(w.end() - w.begin, std::max(w.boundary(1) - w.begin, Eigen::Index(std::lround(0.1 / dt))));
}

// Time from the window's start, reference, output, error, drive: at most
// 4000 points.
std::string time_csv(const TrackingRow& row, double dt) {
  const WindowSamples& w = row.run.window;
  const Eigen::Index n = shown_samples(row, dt);
  const Eigen::Index step = std::max<Eigen::Index>(1, n / 4000);
  std::string out = "t,reference,output,error,input\n";
  for (Eigen::Index k = w.begin; k < w.begin + n; k += step)
    out += gp::number(double(k - w.begin) * dt) + "," + gp::number(row.run.r[k]) + "," + gp::number(row.run.y[k]) +
           "," + gp::number(row.run.y[k] - row.run.r[k]) + "," + gp::number(row.run.u[k]) + "\n";
  return out;
}

std::string time_tics(const TrackingRow& row, double dt) {
  const WindowSamples& w = row.run.window;
  const Eigen::Index n = shown_samples(row, dt);
  figure_script::Span t, y;
  t.add(0.0);
  t.add(double(n - 1) * dt);
  for (Eigen::Index k = w.begin; k < w.begin + n; ++k)
    for (double v : {row.run.r[k], row.run.y[k], row.run.y[k] - row.run.r[k]}) y.add(v);
  return figure_script::xy_tics(t, y);
}

fs::path time_figure(const fs::path& dir, const TrackingExperiment& x, const TrackingRow& row) {
  const std::string name = "tracking_" + table::label_key(row.reference->label);
  write_file_atomic(dir / (name + ".csv"), time_csv(row, x.sample_time));
  const std::string unit = " (" + x.y_unit + ")";
  const std::string plot =
      "  plot \"" + name + ".csv\" using 1:2 with lines lw 2 lc rgb \"black\" title \"reference\", \\\n"
      "       \"" + name + ".csv\" using 1:3 with lines lw 1.5 dt 2 lc rgb \"#d62728\" title \"output\", \\\n"
      "       \"" + name + ".csv\" using 1:4 with lines lw 1.5 lc rgb \"#1f77b4\" title \"error\"\n";
  const std::string text =
      gp::header(name, "reference, output and error at " + row.reference->label + " with " + row.controller->label,
                 name + ".csv") +
      "set datafile separator \",\"\n" + gp::key_above_plot() + "set grid\n" + time_tics(row, x.sample_time) +
      "set title " + gp::quoted(row.reference->label + ", " + row.controller->label) + " noenhanced\n" +
      "set xlabel \"time in the scored window (s)\"\n" + "set ylabel " + gp::quoted("displacement" + unit) +
      " noenhanced\n" + gp::render_all_terminals(name, plot);
  return gp::write_script(dir, name, text);
}

std::string bode_csv(const ControllerDesign& d) {
  std::string out = "hz,full_db,full_deg,reduced_db,reduced_deg\n";
  for (int i = 0; i <= 400; ++i) {
    const double hz = std::pow(10.0, -1.0 + 5.0 * i / 400.0);  // 0.1 Hz to 10 kHz
    out += gp::number(hz);
    for (const auto* k : {&d.full, &d.reduced}) {
      const std::complex<double> g = robust::frequency_response_hz(*k, hz);
      out += "," + gp::number(20.0 * std::log10(std::abs(g))) + "," + gp::number(std::arg(g) * 180.0 / std::numbers::pi);
    }
    out += "\n";
  }
  return out;
}

fs::path bode_figure(const fs::path& dir, const TrackingResults& r) {
  write_file_atomic(dir / "bode.csv", bode_csv(r.design));
  const std::string full = "full order (" + std::to_string(r.design.full.states()) + ")",
                    reduced = "reduced (" + std::to_string(r.design.reduced.states()) + ", " +
                              r.design.reduction.substr(0, r.design.reduction.find(' ')) + ")";
  const auto panel = [&](int column, const std::string& ylabel) {
    return "  set ylabel \"" + ylabel + "\"\n  plot \"bode.csv\" using 1:" + std::to_string(column) +
           " with lines lw 2 lc rgb \"black\" title " + gp::quoted(full) + ", \\\n       \"bode.csv\" using 1:" +
           std::to_string(column + 2) + " with lines lw 1.5 dt 2 lc rgb \"#d62728\" title " + gp::quoted(reduced) + "\n";
  };
  const std::string body = "  set multiplot layout 2, 1 title \"H-infinity feedback controller\"\n" +
                           panel(2, "magnitude (dB)") + "  set xlabel \"frequency (Hz)\"\n" +
                           panel(3, "phase (degree)") + "  unset xlabel\n  unset multiplot\n";
  const std::string text = gp::header("bode", "Bode plot of the full-order and the reduced H-infinity controller",
                                      "bode.csv") +
                           "set datafile separator \",\"\nset logscale x\nset grid\n" + gp::key_above_plot() +
                           gp::render_all_terminals("bode", body, true);
  return gp::write_script(dir, "bode", text);
}

}  // namespace

std::vector<fs::path> write_tracking_figures(const fs::path& dir, const TrackingExperiment& x,
                                             const TrackingResults& r) {
  std::vector<fs::path> scripts{bode_figure(dir, r)};
  const std::size_t shown = shown_controller(x);
  for (std::size_t i = shown; i < r.rows.size(); i += x.controllers.size())
    scripts.push_back(time_figure(dir, x, r.rows[i]));
  return scripts;
}

}  // namespace hystbench
