#pragma once
// The IOHprofiler format that IOHanalyzer reads, built from results folders
// of `hystbench run` (any problem: identification, control or SVR tuning).
//
// One folder per algorithm, as IOHexperimenter's logger leaves them:
//   <algorithm>/IOHprofiler_f<id>_<function>.json    meta data, one run per trial
//   <algorithm>/data_f<id>_<function>/IOHprofiler_f<id>_DIM<d>.dat
// A function is a problem (its name in summary.json); ids count the distinct
// problems from 1 in the order the folders are given. Every trial is
// instance 1: the data set, not the seed, is what IOH calls an instance.
#include <filesystem>
#include <string>
#include <vector>

#include "framework/report/results_reader.hpp"

namespace hystbench {

struct IohFile {
  std::filesystem::path path;  // relative to the export folder
  std::string text;
};

struct IohExport {
  std::vector<IohFile> files;
  long runs = 0;
  // "DE trial 3: failed (...)": failed trials and those with no finite
  // fitness, which the tables count as +inf and IOHanalyzer cannot show.
  std::vector<std::string> skipped;
};

// Folders of one experiment (same name and problem: slices of its trials)
// are merged first; the same label in two experiments on one problem
// becomes "label@experiment".
// InputError when folders of one experiment disagree (see merge_results).
IohExport export_ioh(const std::vector<ResultsFolder>& folders);

// The "evaluations raw_y" rows of one trial: the first point and every strict
// improvement of its trace, then the final evaluation with the final best.
std::vector<std::pair<long, double>> ioh_rows(const TrialResult& trial);

// Letters, digits, '-' and '.' kept, any run of other characters one '_'
// (none at either end): a file-name part.
std::string ioh_safe_name(const std::string& name);

}  // namespace hystbench
