#pragma once
// How every figure script is laid out, chosen once per command
// (`--figure-style`): `screen`, the default, titled and sized for a monitor;
// `paper`, for a journal: no title (the caption says it), a single-column
// width of 8.5 cm or a double-column 17.5 cm for figures of stacked panels,
// and fonts at 8 pt at that printed size, so nothing is scaled down.
#include <string>
#include <vector>

namespace hystbench::gnuplot {

enum class FigureStyle { Screen, Paper };

void set_figure_style(FigureStyle style);
FigureStyle figure_style();

// About how many characters of label text fit side by side across the data
// area of one plot (a `tall` one is the double-column width on paper): a
// figure turns its tic labels, or leaves names out, beyond that.
double characters_across(bool tall = false);

// Whether a key above the plot with these entry titles takes more than two
// rows at the single-column width: such a figure takes the double column.
bool key_needs_double_column(const std::vector<std::string>& titles);

// "screen" or "paper"; InputError naming `where` otherwise.
FigureStyle parse_figure_style(const std::string& text, const std::string& where);

}  // namespace hystbench::gnuplot
