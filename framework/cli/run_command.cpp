#include <omp.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>

#include "framework/cli/commands.hpp"
#include "framework/cli/interrupt_guard.hpp"
#include "framework/cli/number_range.hpp"
#include "framework/cli/output_folder.hpp"
#include "framework/cluster/cluster.hpp"
#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/harness/trial_runner.hpp"
#include "framework/io/measurement.hpp"
#include "framework/harness/trial_log.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/report/resume.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench::cli {
namespace {

struct RunOptions {
  std::string experiment, out, columns, delimiter, trial_range, reference, data;
  int threads = 0;
  long trials = 0;
  long long seed = -1;
  bool force = false;
  bool resume = false;
};

namespace fs = std::filesystem;

// Refuses to mix a new run into old results unless asked to. Only checks:
// nothing is created or removed before every input has been read.
void check_output_folder(const fs::path& dir, const RunOptions& o) {
  hystbench::check_output_folder(dir, "trials.jsonl", o.force || o.resume, "results",
                                 "pass --resume to run only the missing trials, --force to replace them");
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

// Creates the folder and records which run its trials belong to; a folder
// made here is removed again if that fails, so bad output paths leave
// nothing behind either.
void start_output_folder(const fs::path& dir, bool force, const nlohmann::json& identity) {
  std::error_code ec;
  const bool existed = fs::exists(dir);
  // summary.json too: a forced run stopped midway must not look finished.
  if (force)
    for (const char* stale : {"trials.jsonl", "campaign.json", "summary.json"}) fs::remove(dir / stale, ec);
  create_output_folder(dir);
  try {
    write_campaign_identity(dir, identity);
  } catch (const InputError&) {
    if (!existed) fs::remove_all(dir, ec);
    throw;
  }
}

// The command that continues this run, for the message after Ctrl-C.
std::string resume_command(const RunOptions& o, const fs::path& dir) {
  std::string c = "hystbench run " + o.experiment + " --out " + dir.string() + " --resume";
  if (o.trials > 0) c += " --trials " + std::to_string(o.trials);
  if (o.seed >= 0) c += " --seed " + std::to_string(o.seed);
  if (!o.trial_range.empty()) c += " --trial-range " + o.trial_range;
  if (!o.data.empty()) c += " --data " + o.data;
  if (!o.columns.empty()) c += " --columns " + o.columns;
  return c;
}

// What Ctrl-C prints: what is kept, and the command that carries on.
std::string interrupted_message(const RunOptions& o, const fs::path& dir, long done, long total) {
  const std::string kept = " trials finished and are kept in " + (dir / "trials.jsonl").string();
  const std::string state =
      done == total
          ? "all " + std::to_string(total) + kept + "; the report was being written. Write it with:"
          : std::to_string(done) + " of " + std::to_string(total) + kept +
                "; the running ones were abandoned. Resume with:";
  return "interrupted: " + state + "\n  " + resume_command(o, dir);
}

void print_outcome(const fs::path& dir, const WrittenReport& report) {
  std::ifstream table(dir / "table.md");
  std::cout << "\n" << table.rdbuf() << "\n";
  std::cout << "Results in " << dir.string() << ":\n";
  for (const auto& f : report.files) std::cout << "  " << f.string() << "\n";
  for (const auto& f : report.figures) std::cout << "  " << f.string() << "\n";
  if (!report.note.empty()) std::cout << report.note << "\n";
}

Experiment load_experiment(const RunOptions& o) {
  Experiment experiment = Experiment::load(o.experiment);
  if (o.trials > 0) experiment.trials = o.trials;
  if (o.seed >= 0) experiment.seed = static_cast<std::uint64_t>(o.seed);
  if (!o.data.empty()) replace_data(experiment, o.data);
  if (!o.columns.empty() || !o.delimiter.empty()) {
    ColumnMap map = o.columns.empty() ? ColumnMap::from_json(experiment.problem.value("columns", nlohmann::json()),
                                                             "problem.columns")
                                      : ColumnMap::parse(o.columns);
    if (!o.delimiter.empty()) map.delimiter = ColumnMap::parse_delimiter(o.delimiter);
    experiment.problem["columns"] = map.to_json();
  }
  return experiment;
}

// One line before the trials start; with --resume, what is kept and what runs.
void announce(const Experiment& e, const Problem& problem, TrialRange range, int threads,
              std::optional<long> kept, long to_run) {
  std::cerr << "Running " << e.name << ": " << e.algorithms.size() << " algorithm(s) x "
            << range.size() << " trials on " << problem.name() << ", " << threads << " thread(s)";
  if (kept) std::cerr << "; resuming: " << *kept << " finished, " << to_run << " to run";
  std::cerr << "\n";
}

// Problem errors name the experiment file too: the key they name is in it.
std::unique_ptr<Problem> build_problem(const Experiment& experiment, const std::string& file) {
  try {
    auto problem = make_problem(experiment.problem, experiment.base_dir);
    check_polish(experiment, *problem);
    return problem;
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
}

// Everything a run reads, checked before anything is written.
struct RunInputs {
  Experiment experiment;
  TrialRange range;
  std::unique_ptr<Problem> problem;
  fs::path dir;
};

RunInputs read_inputs(const RunOptions& o) {
  if (o.force && o.resume)
    throw InputError("--resume and --force: give one; --resume keeps the finished trials, --force "
                     "discards them");
  RunInputs in;
  in.experiment = load_experiment(o);
  in.range = o.trial_range.empty()
                 ? TrialRange{0, in.experiment.trials}
                 : parse_trial_range(o.trial_range, in.experiment.trials, "--trial-range");
  check_reference(in.experiment, o.reference);
  in.problem = build_problem(in.experiment, o.experiment);
  in.dir = o.out.empty() ? "out/" + in.experiment.name : o.out;
  // Rank 0 alone writes the folder. Another rank checking it could find the
  // trials.jsonl rank 0 has just started (a slow start under mpirun, seen with
  // AddressSanitizer), and on a cluster need not see that file system at all.
  if (cluster::is_coordinator()) check_output_folder(in.dir, o);
  return in;
}

void run(const RunOptions& o) {
  InterruptGuard interrupt;
  const RunInputs in = read_inputs(o);
  const Experiment& experiment = in.experiment;
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  // Under mpirun the ranks other than 0 only run the trials rank 0 hands out.
  if (cluster::is_worker()) return cluster::serve_trials(*in.problem, experiment, threads);
  const auto identity = campaign_identity(experiment, *in.problem, in.range);
  ResumedTrials resumed = o.resume ? resume_trials(in.dir, identity, experiment, in.range) : ResumedTrials{};

  start_output_folder(in.dir, o.force, identity);
  TrialLog log(in.dir / "trials.jsonl");
  const long total = in.range.size() * long(experiment.algorithms.size());
  const long kept = long(resumed.finished.size());
  std::atomic<long> finished{kept};
  interrupt.set_message([&] { return interrupted_message(o, in.dir, finished.load(), total); });
  if (!resumed.warning.empty()) std::cerr << "hystbench: warning: " << resumed.warning << "\n";
  announce(experiment, *in.problem, in.range, threads, o.resume ? std::optional<long>(kept) : std::nullopt,
           total - kept);
  Progress progress(total - kept);
  const auto results = cluster::run_campaign(*in.problem, experiment,
                                    {threads, [&](const TrialResult& r) {
                                       // Under the interrupt lock: Ctrl-C never tears a line.
                                       std::lock_guard<std::mutex> lock(interrupt.mutex());
                                       log.append(r);
                                       ++finished;
                                       progress.trial_done(r);
                                     },
                                     in.range, std::move(resumed.finished)});
  progress.finish();
  print_outcome(in.dir, write_report(in.dir, experiment, *in.problem, results, threads, o.reference));
}

}  // namespace

Action add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand("run", "Run an experiment file: seeded trials of each algorithm, "
                                        "then tables, convergence curves and figures");
  cmd->add_option("experiment", o->experiment, "experiment JSON file")->required();
  cmd->add_option("--out", o->out, "results folder (default: out/<experiment name>)");
  cmd->add_option("--threads", o->threads,
                  "threads: trials in parallel, or, with fewer trials than threads, the "
                  "candidates of each evaluation (default: all cores)")
      ->check(number_range(1, 1024, "give 1 to 1024 threads"));
  cmd->add_option("--trials", o->trials, "override the experiment's number of trials")
      ->check(number_range(1, 1000000, "give 1 to 1000000 trials"));
  cmd->add_option("--seed", o->seed, "override the experiment's seed")
      ->check(number_range(0, kUnbounded, "give a seed of 0 or more"));
  cmd->add_option("--data", o->data,
                  "run the experiment on this data file instead of the one it names (e.g. the "
                  "same algorithms on several data sets, ranked with `hystbench rank`)");
  cmd->add_option("--columns", o->columns,
                  "data columns holding t, u, y (and segment), e.g. t=t_s,u=u_N,y=y_m");
  cmd->add_option("--delimiter", o->delimiter,
                  "between fields of --data: comma, semicolon or tab (default: the header's)");
  cmd->add_option("--trial-range", o->trial_range,
                  "run only trials FROM to TO-1 (0-based, e.g. 0:5) of the experiment, with the "
                  "seeds they have in the full run; merge slices with `hystbench report`");
  add_reference_option(*cmd, o->reference);
  cmd->add_flag("--force", o->force, "replace results already in the --out folder");
  add_figure_style_option(*cmd);
  cmd->add_flag("--resume", o->resume,
                "keep the finished trials in the --out folder (after Ctrl-C or a crash) and run "
                "only the missing ones");
  add_quiet_option(*cmd);
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    cluster::run_on_all_ranks([&] {
      load_plugins();
      run(*o);
    });
  };
}

}  // namespace hystbench::cli
