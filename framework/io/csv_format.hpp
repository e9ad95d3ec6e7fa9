#pragma once
// How numbers and text cells are written in every CSV file hystbench makes.
#include <string>

namespace hystbench {

// %.17g (every double reads back exactly); "inf"/"-inf"; NaN as an empty cell.
std::string csv_number(double x);
// The same with six significant digits (%.6g): for files that feed figures
// only, whose numbers a JSON or table beside them holds in full.
std::string figure_number(double x);

// The text as is, or csv_quoted when it holds a comma, a quote or a line
// break.
std::string csv_field(const std::string& s);
// The text in double quotes, its quotes doubled.
std::string csv_quoted(const std::string& s);

}  // namespace hystbench
