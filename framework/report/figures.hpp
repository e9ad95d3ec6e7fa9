#pragma once
// Figures drawn by gnuplot. Every figure is a self-contained `NAME.gp` script
// next to its data (CSV) that writes NAME.svg, NAME.png and NAME.pdf when run
// with `gnuplot NAME.gp` from the results folder, so users can restyle it.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/report/convergence.hpp"
#include "framework/report/report_context.hpp"

namespace hystbench {

// convergence.gp, reading convergence.csv: log-scale fitness axis, one median
// line with an interquartile band per algorithm. Returns the script path.
std::filesystem::path write_convergence_figure(const std::filesystem::path& dir,
                                               const std::vector<ConvergenceCurve>& curves,
                                               const ReportContext& ctx);

// The best fit of one algorithm against the measurement:
// fit_LABEL.csv (t,u,y_measured,y_model,segment) plus two scripts,
// fit_LABEL_time.gp (measured and model output over time, with residual) and
// fit_LABEL_loops.gp (u-y hysteresis loops, measured and model, one panel per
// segment when segments exist). LABEL is sanitised for file names.
std::vector<std::filesystem::path> write_fit_figures(
    const std::filesystem::path& dir, const std::string& label, const Eigen::VectorXd& t,
    const Eigen::VectorXd& u, const Eigen::VectorXd& y_measured, const Eigen::VectorXd& y_model,
    const std::vector<std::string>& segments, const ReportContext& ctx);

// Runs gnuplot on each script inside `dir`. Returns the rendered image paths.
// When gnuplot is not installed, renders nothing and sets `note` to one line
// saying how to render them later.
std::vector<std::filesystem::path> render_figures(const std::filesystem::path& dir,
                                                  const std::vector<std::filesystem::path>& scripts,
                                                  std::string& note);

}  // namespace hystbench
