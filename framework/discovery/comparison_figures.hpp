#pragma once
// The figures of a comparison report, as gnuplot scripts plus their data
// (rendered with render_figures, figures.hpp):
//   fit_model_time.gp   measured and model output over time, residual below,
//                       segment boundaries marked (write_fit_figures)
//   fit_model_loops.gp  u–y hysteresis loops per segment, measured and model
//   residual.gp         residual over time: held-out spans shaded, segment
//                       boundaries dashed, ± noise σ as dotted lines
//   segment_rmse.gp     RMSE per segment as bars (colour = estimation / held out
//                       / mixed), noise σ as a dashed line
//   correlation.gp      residual autocorrelation (lags 1..25) and input–residual
//                       cross-correlation (−25..25) with the 99 % band
#include <filesystem>
#include <string>
#include <vector>

#include "framework/discovery/comparison.hpp"

namespace hystbench {

struct FigureFiles {
  std::vector<std::filesystem::path> scripts, data;
};

// `metrics` is compare_signals(in). `title` heads the figures.
FigureFiles write_comparison_figures(const std::filesystem::path& dir, const ComparisonInput& in,
                                     const Comparison& metrics, const std::string& title);

}  // namespace hystbench
