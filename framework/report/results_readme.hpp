#pragma once
// README.md of a results folder: how each of its tables was made and how to
// read it. Captions stay short enough for a paper (about 40 words); what a
// careful reader needs beyond them, the method, goes here, one section per
// table, written with the tables.
#include <filesystem>
#include <string>
#include <vector>

namespace hystbench {

struct TableMethod {
  std::string table;  // file stem: "table" for table.md/.tex/.csv
  std::string text;   // Markdown
};

// The README's text. `what`: one paragraph on what made the folder (the
// command and the experiment).
std::string results_readme(const std::string& what, const std::vector<TableMethod>& tables);
void write_results_readme(const std::filesystem::path& dir, const std::string& what,
                          const std::vector<TableMethod>& tables);

}  // namespace hystbench
