#include "framework/report/gnuplot_script.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framework/io/atomic_file.hpp"
#include "framework/report/figure_style.hpp"

namespace hystbench::gnuplot {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

std::string number(double x) {
  if (!std::isfinite(x)) return "NaN";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string one_line(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return s;
}

std::string header(const std::string& name, const std::string& shows, const std::string& reads) {
  return "# " + name + ".gp: " + shows + "\n#\n# Reads " + reads +
         ".\n# To re-render after editing, run inside this folder:\n#     gnuplot " + name +
         ".gp\n# It writes " + name + ".svg, " + name + ".png and " + name +
         ".pdf: the plot commands\n# sit once inside the loop over these three formats at the "
         "end.\n\nset encoding utf8\n";
}

namespace {

// Terminal lines for the screen: sized for a monitor, scaled by the reader.
std::string screen_terminals(bool tall) {
  const std::string svg = tall ? "900,760" : "900,560";
  const std::string pdf = tall ? "6in,5in" : "6in,3.75in";
  return "  if (ext eq \"svg\") { set terminal svg size " + svg +
         " font \"Helvetica,12\" background rgb \"white\" }\n"
         "  if (ext eq \"png\") { set terminal pngcairo size " + svg + " font \"Helvetica,11\" }\n"
         "  if (ext eq \"pdf\") { set terminal pdfcairo size " + pdf + " font \"Helvetica,10\" }\n";
}

// Terminal lines for a journal: printed at 100 %, one column (8.5 cm) or,
// for stacked panels, two (17.5 cm); 8 pt text; the PNG at 300 dpi.
std::string paper_terminals(bool tall) {
  const std::string pdf = tall ? "17.5cm,12cm" : "8.5cm,6cm";
  const std::string png = tall ? "2067,1417" : "1004,709";  // the PDF's size at 300 dpi
  const std::string svg = tall ? "496,340" : "241,170";     // in points
  return "  if (ext eq \"svg\") { set terminal svg size " + svg +
         " font \"Helvetica,8\" background rgb \"white\" }\n"
         "  if (ext eq \"png\") { set terminal pngcairo size " + png +
         " font \"Helvetica,8\" fontscale 4.17 linewidth 4.17 }\n"
         "  if (ext eq \"pdf\") { set terminal pdfcairo size " + pdf + " font \"Helvetica,8\" }\n";
}

// `set multiplot ... title "..." [noenhanced] ...` without the title and its
// options: a stacked figure is captioned like any other.
std::string without_multiplot_title(const std::string& line) {
  const std::size_t key = line.find(" title \"");
  if (key == std::string::npos) return line;
  std::size_t end = key + 8;
  while (end < line.size() && line[end] != '"') end += line[end] == '\\' ? 2 : 1;
  std::string rest = line.substr(std::min(end + 1, line.size()));
  if (rest.rfind(" noenhanced", 0) == 0) rest.erase(0, 11);  // belongs to the title
  return line.substr(0, key) + rest;
}

// The caption carries the title in a paper: every `set title` line of the
// plot commands becomes `unset title`, and the loop starts untitled.
std::string without_titles(const std::string& body) {
  std::string out;
  std::size_t begin = 0;
  while (begin < body.size()) {
    std::size_t end = body.find('\n', begin);
    if (end == std::string::npos) end = body.size();
    const std::string line = body.substr(begin, end - begin);
    const std::size_t text = line.find_first_not_of(' ');
    if (text != std::string::npos && line.compare(text, 10, "set title ") == 0)
      out += line.substr(0, text) + "unset title";
    else if (text != std::string::npos && line.compare(text, 14, "set multiplot ") == 0)
      out += without_multiplot_title(line);
    else
      out += line;
    if (end < body.size()) out += '\n';
    begin = end + 1;
  }
  return out;
}

}  // namespace

std::string render_all_terminals(const std::string& name, const std::string& body, bool tall) {
  const bool paper = figure_style() == FigureStyle::Paper;
  return std::string("\ndo for [ext in \"svg png pdf\"] {\n") +
         (paper ? paper_terminals(tall) + "  unset title\n" : screen_terminals(tall)) +
         "  set output \"" + name + ".\".ext\n" + (paper ? without_titles(body) : body) + "}\nunset output\n";
}

std::string key_above_plot() {
  return "set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1\n";
}

std::filesystem::path write_script(const std::filesystem::path& dir, const std::string& name,
                                   const std::string& text) {
  const std::filesystem::path path = dir / (name + ".gp");
  write_file_atomic(path, text);
  return path;
}

}  // namespace hystbench::gnuplot
