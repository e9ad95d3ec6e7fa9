// `hystbench rank DIR... --out DIR [--control LABEL] [--by mean|median]`:
// the Friedman ranking of the same algorithms over several problems or data
// sets, one results folder of `hystbench run` per data set.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/output_folder.hpp"
#include "framework/core/error.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/ranking_tables.hpp"

namespace hystbench::cli {
namespace {
namespace fs = std::filesystem;

struct RankOptions {
  std::vector<std::string> folders;
  std::string out, control, by = "mean";
  bool force = false;
};

void rank(const RankOptions& o) {
  std::vector<ResultsFolder> folders;
  for (const auto& f : o.folders) folders.push_back(read_results_folder(f));
  const auto statistic = o.by == "median" ? RankStatistic::Median : RankStatistic::Mean;
  const FriedmanRanking ranking = rank_folders(folders, statistic, o.control);
  check_output_folder(o.out, "ranks.md", o.force, "a ranking", "pass --force to replace it");
  create_output_folder(o.out);
  auto files = write_ranking(o.out, ranking);
  std::string note;
  const auto images = render_figures(o.out, {files.back()}, note);
  std::ifstream table(fs::path(o.out) / "ranks.md");
  std::cout << table.rdbuf() << "\nRanking in " << o.out << ":\n";
  for (const auto& f : files) std::cout << "  " << f.string() << "\n";
  for (const auto& f : images) std::cout << "  " << f.string() << "\n";
  if (!note.empty()) std::cout << note << "\n";
}

}  // namespace

Action add_rank_command(CLI::App& app) {
  auto o = std::make_shared<RankOptions>();
  auto* cmd = app.add_subcommand(
      "rank", "Rank the same algorithms over several data sets or problems (one results folder "
              "each) with the Friedman test, Nemenyi CD and Holm tests against a control");
  cmd->add_option("folders", o->folders,
                  "results folders of `hystbench run`, one per data set (at least 2)")
      ->required()
      ->check(CLI::Validator(
          [](const std::string& path) -> std::string {
            if (fs::is_directory(path)) return {};
            return path + (fs::exists(path) ? " is a file" : " does not exist") +
                   "; give results folders of `hystbench run` (plugins go after --plugin)";
          },
          "DIR"));
  cmd->add_option("--out", o->out, "folder for ranks.md/.tex/.csv/.json and ranks.gp")->required();
  cmd->add_option("--control", o->control,
                  "label of the algorithm the others are tested against (default: the best "
                  "average rank)");
  cmd->add_option("--by", o->by, "rank each data set by the mean or the median final fitness")
      ->check(CLI::IsMember({"mean", "median"}))
      ->capture_default_str();
  cmd->add_flag("--force", o->force, "replace a ranking already in the --out folder");
  add_figure_style_option(*cmd);
  // Accepted as by every command that reads results, so that a plugin path is
  // never taken for a results folder.
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    rank(*o);
  };
}

}  // namespace hystbench::cli
