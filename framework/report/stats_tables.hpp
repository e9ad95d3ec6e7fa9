#pragma once
// The statistics table (stats.md, stats.tex, stats.csv), one row per
// algorithm: rank-sum mark against the reference with its Holm-adjusted
// p-value, success rate and ERT to the target, and the median best-so-far
// fitness at 10, 50 and 100 % of the evaluation budget. Nothing in it
// depends on wall time, so merged runs reproduce it byte for byte.
#include <filesystem>
#include <string>

#include "framework/report/report_context.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench {

std::string stats_markdown(const CampaignStatistics& s, const ReportContext& ctx);
// booktabs tabular in a table float; best value per column in bold.
std::string stats_latex(const CampaignStatistics& s, const ReportContext& ctx);
// Full precision, header row, no caption.
std::string stats_csv(const CampaignStatistics& s);
// How the marks, p-values, success rates and ERT are computed, in Markdown,
// for the results folder's README.md (the caption stays short).
std::string stats_method(const CampaignStatistics& s);

void write_stats_tables(const std::filesystem::path& dir, const CampaignStatistics& s,
                        const ReportContext& ctx);

}  // namespace hystbench
