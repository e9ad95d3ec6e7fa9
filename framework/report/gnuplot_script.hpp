#pragma once
// Building blocks of the gnuplot scripts hystbench writes: every figure is a
// self-contained NAME.gp that renders NAME.svg, NAME.png and NAME.pdf with
// the same plot commands. render_figures (figures.hpp) runs the scripts.
#include <filesystem>
#include <string>

namespace hystbench::gnuplot {

// A double-quoted gnuplot string (quotes and backslashes escaped, line
// breaks flattened). Draw user-supplied text `noenhanced`, so '_' or '^'
// in a label are not read as markup.
std::string quoted(const std::string& s);

// %.10g, or NaN (gnuplot skips the point) when x is not finite.
std::string number(double x);

// The text with its line breaks turned into spaces: labels also go into the
// '#' comment lines of data files.
std::string one_line(std::string s);

// Comment block naming the figure, what it shows and which file it reads,
// and how to re-render it; then `set encoding utf8`.
std::string header(const std::string& name, const std::string& shows, const std::string& reads);

// The plot commands `body` wrapped in a loop over the svg, png and pdf
// terminals, so a restyled script keeps the three images identical.
// `tall` picks a taller page for figures with stacked panels (in the paper
// style, figure_style.hpp, the double-column width). The paper style also
// drops the titles.
std::string render_all_terminals(const std::string& name, const std::string& body,
                                 bool tall = false);

// `set key` above the plot area, centred, entries side by side: the legend
// of every figure with several curves, outside the data and as wide as the
// plot rather than a column beside it.
std::string key_above_plot();

// Writes dir/NAME.gp atomically and returns its path.
std::filesystem::path write_script(const std::filesystem::path& dir, const std::string& name,
                                   const std::string& text);

}  // namespace hystbench::gnuplot
