#pragma once
// The Friedman ranking of several results folders (friedman_ranking.hpp) as
// a paper table and a figure, in the results-table style of stats.md:
//   ranks.md / ranks.tex  one row per algorithm: its rank in each data set,
//                         the average rank (best in bold), the Holm mark and
//                         p-value against the control; the caption states
//                         the test statistics and the Nemenyi CD
//   ranks.csv             the same with full precision and the values ranked
//   ranks.json            the test statistics, for scripts
//   ranks.gp              average ranks with Nemenyi intervals (ranking_figure.hpp)
#include <filesystem>
#include <string>
#include <vector>

#include "framework/report/friedman_ranking.hpp"

namespace hystbench {

std::string ranking_markdown(const FriedmanRanking& r);
// How the ranks and tests were made, in Markdown, for the folder's README.md.
std::string ranking_method(const FriedmanRanking& r);
// booktabs tabular in a table float.
std::string ranking_latex(const FriedmanRanking& r);
std::string ranking_csv(const FriedmanRanking& r);
nlohmann::json ranking_json(const FriedmanRanking& r);

// Writes the tables, ranks.json and the figure script; returns the files
// written, the script last.
std::vector<std::filesystem::path> write_ranking(const std::filesystem::path& dir,
                                                 const FriedmanRanking& r);

}  // namespace hystbench
