#pragma once
// How numbers and text cells are written in every CSV file hystbench makes.
#include <string>

namespace hystbench {

// %.17g (every double reads back exactly); "inf"/"-inf"; NaN as an empty cell.
std::string csv_number(double x);

// The text as is, or double-quoted (quotes doubled) when it holds a comma,
// a quote or a line break.
std::string csv_field(const std::string& s);

}  // namespace hystbench
