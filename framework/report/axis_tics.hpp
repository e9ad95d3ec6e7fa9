#pragma once
// Tic spacing for figure panels. gnuplot's automatic tics ignore the panel
// size, so short or narrow panels (and the paper style's single column)
// get them from here.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hystbench::figure_script {

// The range of the finite values added.
struct Span {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  void add(double x) {
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  }
};

// 1, 2 or 5 times a power of ten, nearest to `intervals` tic intervals:
// gnuplot's own spacing ignores the panel height and crowds short panels.
// 0 (gnuplot's choice) when the data has no width.
double tic_step(const Span& s, double intervals);

// About `intervals` tic intervals, only over the data, so none is drawn in
// the strip kept free above it.
std::string ytics(const Span& s, double intervals);

// Symmetric about zero, so a bias of the model shows as an off-centre
// band; three tics fit even the short panel of the PDF.
std::string residual_axis(const Span& s);

// `set xtics STEP` and `set ytics STEP` lines for a plot of x against y:
// about five intervals each, three in the paper style's single column.
std::string xy_tics(const Span& x, const Span& y);

}  // namespace hystbench::figure_script
