#include "framework/report/gnuplot_script.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framework/io/atomic_file.hpp"

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

std::string render_all_terminals(const std::string& name, const std::string& body, bool tall) {
  const std::string svg = tall ? "900,760" : "900,560";
  const std::string pdf = tall ? "6in,5in" : "6in,3.75in";
  return "\ndo for [ext in \"svg png pdf\"] {\n"
         "  if (ext eq \"svg\") { set terminal svg size " +
         svg +
         " font \"Helvetica,12\" "
         "background rgb \"white\" }\n"
         "  if (ext eq \"png\") { set terminal pngcairo size " +
         svg +
         " font \"Helvetica,11\" }\n"
         "  if (ext eq \"pdf\") { set terminal pdfcairo size " +
         pdf +
         " font \"Helvetica,10\" }\n"
         "  set output \"" +
         name + ".\".ext\n" + body + "}\nunset output\n";
}

std::filesystem::path write_script(const std::filesystem::path& dir, const std::string& name,
                                   const std::string& text) {
  const std::filesystem::path path = dir / (name + ".gp");
  write_file_atomic(path, text);
  return path;
}

}  // namespace hystbench::gnuplot
