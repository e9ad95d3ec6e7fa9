// `hystbench export ioh DIR... --out OUT`: the runs of results folders in the
// IOHprofiler format, for IOHanalyzer (framework/export/ioh_export.hpp).
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <vector>

#include "framework/cli/commands.hpp"
#include "framework/cli/output_folder.hpp"
#include "framework/core/error.hpp"
#include "framework/export/ioh_export.hpp"
#include "framework/io/atomic_file.hpp"

namespace hystbench::cli {
namespace {
namespace fs = std::filesystem;

struct ExportOptions {
  std::vector<std::string> folders;
  std::string out;
  bool force = false;
};

// The files of an earlier export in `out`: IOHanalyzer would mix its runs
// with the new ones.
std::vector<fs::path> earlier_export(const fs::path& out) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (!fs::is_directory(out, ec)) return found;
  for (const auto& folder : fs::directory_iterator(out))
    if (folder.is_directory())
      for (const auto& e : fs::directory_iterator(folder.path())) {
        const std::string name = e.path().filename().string();
        if ((name.starts_with("IOHprofiler_") && name.ends_with(".json")) ||
            (e.is_directory() && name.starts_with("data_f")))
          found.push_back(e.path());
      }
  return found;
}

void replace_earlier_export(const fs::path& out, bool force) {
  const auto earlier = earlier_export(out);
  if (earlier.empty()) return;
  if (!force)
    throw InputError("--out " + out.string() + ": already holds an IOHprofiler export; pass "
                     "--force to replace it, or choose another folder with --out");
  for (const auto& p : earlier) fs::remove_all(p);
}

void export_ioh_folders(const ExportOptions& o) {
  std::vector<ResultsFolder> folders;
  for (const auto& f : o.folders) folders.push_back(read_results_folder(f));
  const IohExport exported = export_ioh(folders);
  if (exported.files.empty())
    throw InputError("nothing to export: no trial of the folders given has a finite fitness");
  const fs::path out = o.out;
  // Any file of an earlier export counts, not one marker file: see earlier_export.
  check_output_path(out);
  replace_earlier_export(out, o.force);
  std::set<fs::path> algorithms;
  for (const auto& f : exported.files) {
    create_output_folder((out / f.path).parent_path());
    write_file_atomic(out / f.path, f.text);
    algorithms.insert(*f.path.begin());
  }
  std::cout << "Exported " << exported.runs << (exported.runs == 1 ? " run" : " runs") << " of "
            << algorithms.size() << (algorithms.size() == 1 ? " algorithm" : " algorithms")
            << " to " << out.string() << " (IOHprofiler format).\n";
  for (const auto& s : exported.skipped) std::cout << "  skipped " << s << "\n";
  std::cout << "For IOHanalyzer (Upload Data), zip the folder's contents, e.g. cd '"
            << out.string() << "' && zip -r ../ioh_export.zip .\n";
}

}  // namespace

Action add_export_command(CLI::App& app) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand("export", "Write results in the formats of other tools");
  cmd->require_subcommand(1);
  auto* ioh = cmd->add_subcommand(
      "ioh", "The runs of results folders of `hystbench run` in the IOHprofiler format that "
             "IOHanalyzer reads: one folder per algorithm, one run per trial");
  ioh->add_option("folders", o->folders,
                  "results folders of `hystbench run` (slices of one experiment are merged)")
      ->required()
      ->check(CLI::ExistingDirectory);
  ioh->add_option("--out", o->out, "folder for the export (zip it to upload)")->required();
  ioh->add_flag("--force", o->force,
                "replace an export already in the --out folder (its algorithm folders' "
                "IOHprofiler files)");
  auto load_plugins = add_plugin_option(*ioh);
  return [o, load_plugins] {
    load_plugins();
    export_ioh_folders(*o);
  };
}

}  // namespace hystbench::cli
