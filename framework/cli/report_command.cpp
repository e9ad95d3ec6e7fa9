// `hystbench report DIR... [--out DIR] [--reference LABEL]`: recomputes
// every table and figure from the trials of one or more results folders,
// merging folders that hold disjoint trials of the same experiment.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/output_folder.hpp"
#include "framework/core/error.hpp"
#include "framework/core/plugin_loader.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/report/results_merge.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench::cli {
namespace {
namespace fs = std::filesystem;

struct ReportOptions {
  std::vector<std::string> folders;
  std::string out, reference, base_dir;
  bool force = false;
};

bool same_folder(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

fs::path output_folder(const ReportOptions& o) {
  if (!o.out.empty()) return o.out;
  if (o.folders.size() == 1) return o.folders[0];
  throw InputError("--out: required when merging several results folders");
}

bool is_input(const ReportOptions& o, const fs::path& dir) {
  for (const auto& f : o.folders)
    if (same_folder(f, dir)) return true;
  return false;
}

// A new folder gets the merged trials.jsonl, sorted by algorithm and trial;
// an input folder keeps its own.
void prepare_output(const ReportOptions& o, const fs::path& dir, const MergedResults& m) {
  if (is_input(o, dir)) {
    if (o.folders.size() > 1)
      throw InputError("--out " + dir.string() + ": is one of the merged folders; choose a new "
                       "folder so that its trials.jsonl is not replaced");
    return;
  }
  check_output_folder(dir, "trials.jsonl", o.force, "results", "pass --force to replace them");
  create_output_folder(dir);
  std::string lines;
  for (const auto& trials : m.results)
    for (const auto& r : trials) lines += r.to_json().dump() + "\n";
  write_file_atomic(dir / "trials.jsonl", lines);
}

std::unique_ptr<Problem> rebuild_problem(const Experiment& e) {
  const fs::path& base = e.base_dir;
  try {
    return make_problem(e.problem, base);
  } catch (const InputError& err) {
    throw InputError(std::string("cannot rebuild the experiment's problem: ") + err.what() +
                     " (relative paths resolve against " + base.string() +
                     "; point --base-dir at the folder of the experiment file)");
  }
}

void write_merged_report(const ReportOptions& o, const std::vector<ResultsFolder>& folders) {
  MergedResults merged = merge_results(folders);
  check_reference(merged.experiment, o.reference);
  if (!o.base_dir.empty()) merged.experiment.base_dir = o.base_dir;
  const fs::path dir = output_folder(o);
  const auto problem = rebuild_problem(merged.experiment);
  prepare_output(o, dir, merged);
  const int threads = folders[0].summary["provenance"].value("threads", 1);
  const auto written =
      write_report(dir, merged.experiment, *problem, merged.results, threads, o.reference);
  std::ifstream table(dir / "stats.md");
  std::cout << table.rdbuf() << "\nReport in " << dir.string() << ":\n";
  for (const auto& f : written.files) std::cout << "  " << f.string() << "\n";
  for (const auto& f : written.figures) std::cout << "  " << f.string() << "\n";
  if (!written.note.empty()) std::cout << written.note << "\n";
}

// "R was made with --plugin A.so (x, y); pass the same" for the plugins a
// folder's provenance records and this run has not loaded; "" otherwise.
std::string missing_plugins(const std::vector<ResultsFolder>& folders) {
  std::string advice;
  for (const auto& f : folders) {
    std::string flags;
    const auto recorded = f.summary.value("provenance", nlohmann::json::object())
                              .value("plugins", nlohmann::json::array());
    for (const auto& p : recorded) {
      const std::string path = p.value("path", "");
      bool loaded = false;
      for (const auto& l : loaded_plugins()) loaded = loaded || l.path == path;
      if (!loaded)
        flags += (flags.empty() ? "" : " ") + std::string("--plugin ") + path + " (" +
                 join(p.value("names", std::vector<std::string>{})) + ")";
    }
    if (!flags.empty()) advice += f.dir.string() + " was made with " + flags + "; pass the same. ";
  }
  return advice;
}

void report(const ReportOptions& o) {
  std::vector<ResultsFolder> folders;
  for (const auto& f : o.folders) folders.push_back(read_results_folder(f));
  try {
    write_merged_report(o, folders);
  } catch (const InputError& e) {
    const std::string advice = missing_plugins(folders);
    if (advice.empty()) throw;
    throw InputError(std::string(e.what()) + ". " + advice.substr(0, advice.size() - 1));
  }
}

}  // namespace

Action add_report_command(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  auto* cmd = app.add_subcommand(
      "report", "Recompute the tables and figures of results folders from their trials.jsonl, "
                "merging folders that hold disjoint trials of one experiment");
  cmd->add_option("folders", o->folders, "results folders of `hystbench run`")->required();
  cmd->add_option("--out", o->out,
                  "folder of the report (default: the folder given; required for several)");
  add_reference_option(*cmd, o->reference);
  cmd->add_option("--base-dir", o->base_dir,
                  "folder that relative data paths of the experiment resolve against (default: "
                  "the experiment file's folder recorded by `run`)");
  cmd->add_flag("--force", o->force, "replace results already in the --out folder");
  add_figure_style_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    report(*o);
  };
}

}  // namespace hystbench::cli
