#pragma once
// Figures of the comparison statistics, drawn like the convergence figure
// (a NAME.gp script beside its data, rendered by render_figures):
//   ecdf.gp    fraction of trials that reached the target against
//              evaluations (log x), one step line per algorithm; data in
//              ecdf.csv (label,evaluations,fraction) and ecdf.dat
//   boxplot.gp final fitness per algorithm (log y when all are positive);
//              data in boxplot.csv (label,trial,final) and boxplot.dat
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"
#include "framework/report/report_context.hpp"

namespace hystbench {

// Returns the script path; nullopt (and no files) without a target.
std::optional<std::filesystem::path> write_ecdf_figure(
    const std::filesystem::path& dir, const Experiment& e,
    const std::vector<std::vector<TrialResult>>& results, std::optional<double> target,
    const ReportContext& ctx);

std::filesystem::path write_boxplot_figure(const std::filesystem::path& dir, const Experiment& e,
                                           const std::vector<std::vector<TrialResult>>& results,
                                           const ReportContext& ctx);

}  // namespace hystbench
