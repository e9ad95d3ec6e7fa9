#pragma once
// The fit figures of one algorithm's best fit against the measurement,
// apart from the convergence figure because they are drawn from one fit's
// time series. Rendered like every figure by render_figures
// (figure_rendering.hpp).
#include "framework/core/eigen.hpp"
#include <filesystem>
#include <string>
#include <vector>

#include "framework/report/report_context.hpp"

namespace hystbench {

// The best fit of one algorithm against the measurement:
// fit_LABEL.csv (t,u,y_measured,y_model,segment) plus two scripts,
// fit_LABEL_time.gp (measured and model output over time, with residual) and
// fit_LABEL_loops.gp (u-y hysteresis loops, measured and model, one panel per
// segment when segments exist). LABEL is sanitised for file names.
std::vector<std::filesystem::path> write_fit_figures(
    const std::filesystem::path& dir, const std::string& label, const Eigen::VectorXd& t,
    const Eigen::VectorXd& u, const Eigen::VectorXd& y_measured, const Eigen::VectorXd& y_model,
    const std::vector<std::string>& segments, const ReportContext& ctx);

}  // namespace hystbench
