#pragma once
// Pieces of the Markdown reports (report.md, ladder.md): numbers and
// GitHub-flavoured tables.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hystbench::markdown {

// "%.4g" of a number; "–" for null, non-numbers and non-finite values.
std::string num(const nlohmann::json& j);
std::string num(double x);
// A table cell: '|' escaped, line breaks flattened, never empty.
std::string cell(const std::string& s);
// "| a | b |\n"
std::string row(const std::vector<std::string>& cells);
// The header row and the alignment rule: per column 'l' (left) or 'r'
// (right) from `align`; empty: first column left, the others right.
std::string header_row(const std::vector<std::string>& cells, const std::string& align = "");

}  // namespace hystbench::markdown
