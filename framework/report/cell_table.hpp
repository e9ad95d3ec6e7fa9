#pragma once
// A table of ready-made cells (already formatted and escaped for the
// format) as Markdown or as a booktabs LaTeX float: first column left, the
// others right.
#include <string>
#include <vector>

namespace hystbench::table {

struct CellTable {
  std::string caption;  // in the target format
  std::string label;    // LaTeX \label key (label_key() applied by the caller)
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// "**Table.** caption", a blank line, then the table.
std::string markdown(const CellTable& t);
// A table float with \caption and \label; needs \usepackage{booktabs}.
std::string latex(const CellTable& t);

}  // namespace hystbench::table
