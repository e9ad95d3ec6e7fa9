#pragma once
// The convergence figure, apart from the other figures because it is drawn
// from the convergence curves of a whole campaign rather than one fit.
// Rendered like every figure by render_figures (figure_rendering.hpp).
#include <filesystem>
#include <vector>

#include "framework/report/convergence.hpp"
#include "framework/report/report_context.hpp"

namespace hystbench {

// convergence.gp, reading convergence.csv: log-scale fitness axis, one median
// line with an interquartile band per algorithm. Returns the script path.
std::filesystem::path write_convergence_figure(const std::filesystem::path& dir,
                                               const std::vector<ConvergenceCurve>& curves,
                                               const ReportContext& ctx);

}  // namespace hystbench
