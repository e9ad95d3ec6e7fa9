#include <omp.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cluster/cluster.hpp"
#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/io/measurement.hpp"
#include "framework/io/trial_log.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench::cli {
namespace {

struct RunOptions {
  std::string experiment, out, columns, trial_range, reference, data;
  int threads = 0;
  long trials = 0;
  long long seed = -1;
  bool force = false;
};

// Refuses to mix a new run into old results unless asked to.
void prepare_output_folder(const std::filesystem::path& dir, bool force) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError("--out " + dir.string() + ": exists and is not a folder");
  if (fs::exists(dir / "trials.jsonl")) {
    if (!force)
      throw InputError("--out " + dir.string() + ": already holds results; pass --force to replace "
                       "them or choose another folder with --out");
    fs::remove(dir / "trials.jsonl", ec);
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir.string() + ": cannot create this folder: " + ec.message());
}

// --data replaces the experiment's data file. The path is stored relative to
// the experiment file's folder, where relative data paths resolve, so that
// summary.json names no folder of this machine and `report` finds the file.
void replace_data(Experiment& e, const std::string& data) {
  namespace fs = std::filesystem;
  if (!e.problem.contains("data"))
    throw InputError("--data: the experiment's problem (" + e.problem.value("type", "?") +
                     ") reads no data file");
  if (!fs::is_regular_file(data)) throw InputError("--data " + data + ": file not found");
  std::error_code ec;
  const auto file = fs::absolute(data, ec).lexically_normal();
  const auto base = fs::absolute(e.base_dir, ec).lexically_normal();
  const auto relative = file.lexically_relative(base);
  e.problem["data"] = (relative.empty() ? file : relative).generic_string();
}

void print_outcome(const std::filesystem::path& dir, const WrittenReport& report) {
  std::ifstream table(dir / "table.md");
  std::cout << "\n" << table.rdbuf() << "\n";
  std::cout << "Results in " << dir.string() << ":\n";
  for (const auto& f : report.files) std::cout << "  " << f.string() << "\n";
  for (const auto& f : report.figures) std::cout << "  " << f.string() << "\n";
  if (!report.note.empty()) std::cout << report.note << "\n";
}

void run(const RunOptions& o) {
  Experiment experiment = Experiment::load(o.experiment);
  if (o.trials > 0) experiment.trials = o.trials;
  if (o.seed >= 0) experiment.seed = static_cast<std::uint64_t>(o.seed);
  if (!o.data.empty()) replace_data(experiment, o.data);
  if (!o.columns.empty()) experiment.problem["columns"] = ColumnMap::parse(o.columns).to_json();
  const TrialRange range = o.trial_range.empty()
                               ? TrialRange{0, experiment.trials}
                               : parse_trial_range(o.trial_range, experiment.trials, "--trial-range");
  check_reference(experiment, o.reference);
  const auto problem = make_problem(experiment.problem, experiment.base_dir);
  const std::filesystem::path dir = o.out.empty() ? "out/" + experiment.name : o.out;
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  // Under mpirun the ranks other than 0 only run the trials rank 0 hands out.
  if (cluster::is_worker()) return cluster::serve_trials(*problem, experiment, threads);

  prepare_output_folder(dir, o.force);
  TrialLog log(dir / "trials.jsonl");
  Progress progress(range.size() * long(experiment.algorithms.size()), stderr_is_terminal());
  std::cerr << "Running " << experiment.name << ": " << experiment.algorithms.size() << " algorithm(s) x "
            << range.size() << " trials on " << problem->name() << ", " << threads << " thread(s)\n";
  const auto results = cluster::run_campaign(*problem, experiment,
                                    {threads, [&](const TrialResult& r) {
                                       log.append(r);
                                       progress.trial_done(r);
                                     },
                                     range});
  progress.finish();
  print_outcome(dir, write_report(dir, experiment, *problem, results, threads, o.reference));
}

}  // namespace

Action add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand("run", "Run an experiment file: seeded trials of each algorithm, "
                                        "then tables, convergence curves and figures");
  cmd->add_option("experiment", o->experiment, "experiment JSON file")->required();
  cmd->add_option("--out", o->out, "results folder (default: out/<experiment name>)");
  cmd->add_option("--threads", o->threads, "trials run in parallel (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--trials", o->trials, "override the experiment's number of trials")
      ->check(CLI::Range(1L, 1000000L));
  cmd->add_option("--seed", o->seed, "override the experiment's seed")->check(CLI::NonNegativeNumber);
  cmd->add_option("--data", o->data,
                  "run the experiment on this data file instead of the one it names (e.g. the "
                  "same algorithms on several data sets, ranked with `hystbench rank`)");
  cmd->add_option("--columns", o->columns,
                  "data columns holding t, u, y (and segment), e.g. t=t_s,u=u_N,y=y_m");
  cmd->add_option("--trial-range", o->trial_range,
                  "run only trials FROM to TO-1 (0-based, e.g. 0:5) of the experiment, with the "
                  "seeds they have in the full run; merge slices with `hystbench report`");
  add_reference_option(*cmd, o->reference);
  cmd->add_flag("--force", o->force, "replace results already in the --out folder");
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    cluster::run_on_all_ranks([&] {
      load_plugins();
      run(*o);
    });
  };
}

}  // namespace hystbench::cli
