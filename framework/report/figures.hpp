#pragma once
// Figures drawn by gnuplot. Every figure is a self-contained `NAME.gp` script
// next to its data (CSV) that writes NAME.svg, NAME.png and NAME.pdf when run
// with `gnuplot NAME.gp` from the results folder, so users can restyle it.
// Each kind of figure has its own header; this one gathers them, so a
// report that draws several figures needs one include.
#include "framework/report/convergence_figure.hpp"
#include "framework/report/figure_rendering.hpp"
#include "framework/report/fit_figures.hpp"
