// Tic spacing of figure panels: 1, 2 or 5 times a power of ten, chosen from
// the data so that short or narrow panels are not crowded.
#include "framework/report/axis_tics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/report/figure_style.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench::figure_script {

double tic_step(const Span& s, double intervals) {
  const double raw = (s.hi - s.lo) / intervals;
  if (!(raw > 0) || !std::isfinite(raw)) return 0.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double best = decade;
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(std::log(m * decade / raw)) < std::abs(std::log(best / raw))) best = m * decade;
  return best;
}

std::string ytics(const Span& s, double intervals) {
  const double step = tic_step(s, intervals);
  if (step == 0) return "  set ytics autofreq\n";
  const double first = std::ceil(s.lo / step) * step + 0.0;  // + 0.0: no "-0"
  return "  set ytics " + gnuplot::number(first) + ", " + gnuplot::number(step) + ", " + gnuplot::number(s.hi) + "\n";
}

std::string residual_axis(const Span& s) {
  const double m = std::max(std::abs(s.lo), std::abs(s.hi));
  if (!(m > 0) || !std::isfinite(m)) return "  set yrange [-1:1]\n  set ytics autofreq\n";
  // The largest 1, 2 or 5 times a power of ten that still fits, so the
  // tics at +-step are inside the range.
  const double decade = std::pow(10.0, std::floor(std::log10(m)));
  const double step = m >= 5 * decade ? 5 * decade : (m >= 2 * decade ? 2 * decade : decade);
  return "  set yrange [" + gnuplot::number(-1.08 * m) + ":" + gnuplot::number(1.08 * m) + "]\n  set ytics " +
         gnuplot::number(-step) + ", " + gnuplot::number(step) + ", " + gnuplot::number(step) + "\n";
}

std::string xy_tics(const Span& x, const Span& y) {
  const double intervals = gnuplot::figure_style() == gnuplot::FigureStyle::Paper ? 3 : 5;
  const double x_step = tic_step(x, intervals), y_step = tic_step(y, intervals);
  return (x_step > 0 ? "set xtics " + gnuplot::number(x_step) + "\n" : "") +
         (y_step > 0 ? "set ytics " + gnuplot::number(y_step) + "\n" : "");
}

}  // namespace hystbench::figure_script
