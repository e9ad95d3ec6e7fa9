#include "framework/report/cell_table.hpp"

#include "framework/core/text.hpp"

namespace hystbench::table {

std::string markdown(const CellTable& t) {
  std::string out = "**Table.** " + t.caption + "\n\n| " + join(t.header, " | ") + " |\n|:---";
  for (std::size_t i = 1; i < t.header.size(); ++i) out += "|---:";
  out += "|\n";
  for (const auto& cells : t.rows) out += "| " + join(cells, " | ") + " |\n";
  return out;
}

std::string latex(const CellTable& t) {
  std::string out = "% Requires \\usepackage{booktabs}.\n\\begin{table}[htbp]\n  \\centering\n";
  out += "  \\caption{" + t.caption + "}\n  \\label{tab:" + t.label + "}\n";
  out += "  \\footnotesize\n  \\setlength{\\tabcolsep}{3pt}\n";
  out += "  \\begin{tabular}{l" + std::string(t.header.size() - 1, 'r') + "}\n    \\toprule\n";
  out += "    " + join(t.header, " & ") + " \\\\\n    \\midrule\n";
  for (const auto& cells : t.rows) out += "    " + join(cells, " & ") + " \\\\\n";
  return out + "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
}

}  // namespace hystbench::table
