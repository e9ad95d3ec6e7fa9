#pragma once
// Writing a diagnosis out: diagnosis.json, report.md (an answer a researcher
// can act on: where the model fails, which effect is missing and why we
// think so, how much adding it helps) and the candidates figure
// (candidates_figure.hpp).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/data_source.hpp"
#include "framework/discovery/diagnosis.hpp"

namespace hystbench {

// The report.md text. `current_report` is the relative path of the current
// fit's comparison report (linked for the details).
std::string diagnosis_markdown(const Diagnosis& d, const std::string& data_name,
                               const std::string& y_unit, const std::string& current_report);

// Everything a diagnosis leaves in `dir`: diagnosis.json, report.md,
// fit.json (the current model as diagnosed), extended_fit.json (with the
// winner added, when there is one), current/ (compare's report of the
// current fit) and the candidates figure. Returns the files written; sets
// `note` when figures could not be rendered.
std::vector<std::filesystem::path> write_diagnosis(const std::filesystem::path& dir,
                                                   const Diagnosis& d, const ModelData& data,
                                                   const DataSource& source,
                                                   const HoldoutSpec& holdout, std::string& note);

}  // namespace hystbench
