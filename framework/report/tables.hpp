#pragma once
// The results table in three formats, one row per algorithm.
//
// Columns (docs/usage.md#outputs defines each): Algorithm, f_avg, f_max,
// f_min, f_std, Median, Iterations, Evaluations, Failed; the seed's layout
// (ReportContext::seed_table_layout) adds Best fitness value before f_avg,
// equal to f_min by definition, as MEDE's Table 1 prints it. The CSV always
// has every column.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/harness/algorithm_summary.hpp"
#include "framework/report/report_context.hpp"

namespace hystbench {

std::string table_markdown(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx);
// booktabs tabular inside a table float with a caption; best value per
// fitness column in bold.
std::string table_latex(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx);
// Full double precision (17 significant digits), header row, no caption.
std::string table_csv(const std::vector<AlgorithmSummary>& rows);

// How the table is made and read, in Markdown: the results folder's README.md
// holds it, the caption stays short.
std::string table_method(const ReportContext& ctx);

// Writes table.md, table.tex and table.csv into `dir` (atomically).
void write_tables(const std::filesystem::path& dir, const std::vector<AlgorithmSummary>& rows,
                  const ReportContext& ctx);

}  // namespace hystbench
