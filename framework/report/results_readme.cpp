#include "framework/report/results_readme.hpp"

#include "framework/io/atomic_file.hpp"

namespace hystbench {

std::string results_readme(const std::string& what, const std::vector<TableMethod>& tables) {
  std::string text = "# How to read this folder\n\n" + what +
                     "\n\nEach table's caption says what it shows; how its numbers were made is "
                     "below. The same tables are in `.md`, `.tex` (booktabs) and `.csv` (full "
                     "precision).\n";
  for (const TableMethod& t : tables) text += "\n## " + t.table + ".md\n\n" + t.text + "\n";
  return text;
}

void write_results_readme(const std::filesystem::path& dir, const std::string& what,
                          const std::vector<TableMethod>& tables) {
  write_file_atomic(dir / "README.md", results_readme(what, tables));
}

}  // namespace hystbench
