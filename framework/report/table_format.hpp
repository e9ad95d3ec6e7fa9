#pragma once
// Cell text shared by the results tables (tables.hpp) and the statistics
// tables (stats_tables.hpp), so that both print numbers the same way.
#include <string>

namespace hystbench::table {

enum class Format { Markdown, Latex };

// Four significant digits; scientific notation outside [1e-3, 1e4).
std::string format_fitness(double x, Format f);
// Whole numbers stay whole, others get one decimal.
std::string format_count(double x, Format f);
// "—" for NaN, "∞" for infinity (their LaTeX forms in LaTeX).
std::string non_finite(double x, Format f);
std::string bold(const std::string& cell, Format f);
// Bold when the cell reads as the column's best: two cells that print the
// same are both best to a reader, whatever digits the table does not show.
// An empty best_text (a column with no best) bolds nothing.
std::string bold_if_best(const std::string& cell, const std::string& best_text, Format f);
// "α = 0.05", in math mode for LaTeX.
std::string significance_level(double alpha, Format f);
std::string escape_latex(const std::string& s);
std::string escape_markdown(const std::string& s);
std::string escape(const std::string& s, Format f);
// A \label key: anything unusual becomes '-'.
std::string label_key(const std::string& s);

}  // namespace hystbench::table
