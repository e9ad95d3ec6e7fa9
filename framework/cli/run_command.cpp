#include <omp.h>

#include <atomic>
#include <fstream>
#include <mutex>
#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/cli/interrupt_guard.hpp"
#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/progress.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/io/measurement.hpp"
#include "framework/io/trial_log.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/report/resume.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench::cli {
namespace {

struct RunOptions {
  std::string experiment, out, columns, trial_range, reference;
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
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError("--out " + dir.string() + ": exists and is not a folder; choose another "
                     "folder with --out");
  if (fs::exists(dir / "trials.jsonl") && !o.force && !o.resume)
    throw InputError("--out " + dir.string() + ": already holds results; pass --resume to run "
                     "only the missing trials, --force to replace them, or choose another folder "
                     "with --out");
}

// Creates the folder and records which run its trials belong to; a folder
// made here is removed again if that fails, so bad output paths leave
// nothing behind either.
void start_output_folder(const fs::path& dir, bool force, const nlohmann::json& identity) {
  std::error_code ec;
  const bool existed = fs::exists(dir);
  if (force) {
    fs::remove(dir / "trials.jsonl", ec);
    fs::remove(dir / "campaign.json", ec);
  }
  fs::create_directories(dir, ec);
  if (ec)
    throw InputError("--out " + dir.string() + ": cannot create this folder (" + ec.message() +
                     "); choose a folder you can write to with --out");
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
  if (!o.columns.empty()) c += " --columns " + o.columns;
  return c;
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
  if (!o.columns.empty()) experiment.problem["columns"] = ColumnMap::parse(o.columns).to_json();
  return experiment;
}

// Problem errors name the experiment file too: the key they name is in it.
std::unique_ptr<Problem> build_problem(const Experiment& experiment, const std::string& file) {
  try {
    return make_problem(experiment.problem, experiment.base_dir);
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
}

void run(const RunOptions& o) {
  InterruptGuard interrupt;
  if (o.force && o.resume)
    throw InputError("--resume and --force: give one; --resume keeps the finished trials, --force "
                     "discards them");
  const Experiment experiment = load_experiment(o);
  const TrialRange range = o.trial_range.empty()
                               ? TrialRange{0, experiment.trials}
                               : parse_trial_range(o.trial_range, experiment.trials, "--trial-range");
  check_reference(experiment, o.reference);
  const auto problem = build_problem(experiment, o.experiment);
  const fs::path dir = o.out.empty() ? "out/" + experiment.name : o.out;
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  check_output_folder(dir, o);
  const auto identity = campaign_identity(experiment, *problem, range);
  ResumedTrials resumed;
  if (o.resume) resumed = resume_trials(dir, identity, experiment, range);

  start_output_folder(dir, o.force, identity);
  TrialLog log(dir / "trials.jsonl");
  const long total = range.size() * long(experiment.algorithms.size());
  const long to_run = total - long(resumed.finished.size());
  std::atomic<long> finished{long(resumed.finished.size())};
  interrupt.set_message([&] {
    return "interrupted: " + std::to_string(finished.load()) + " of " + std::to_string(total) +
           " trials finished and are kept in " + (dir / "trials.jsonl").string() +
           "; the running ones were abandoned. Resume with:\n  " + resume_command(o, dir);
  });
  if (!resumed.warning.empty()) std::cerr << "hystbench: warning: " << resumed.warning << "\n";
  Progress progress(to_run, stderr_is_terminal());
  std::cerr << "Running " << experiment.name << ": " << experiment.algorithms.size() << " algorithm(s) x "
            << range.size() << " trials on " << problem->name() << ", " << threads << " thread(s)";
  if (o.resume) std::cerr << "; resuming: " << resumed.finished.size() << " finished, " << to_run << " to run";
  std::cerr << "\n";
  const auto results = run_campaign(*problem, experiment,
                                    {threads, [&](const TrialResult& r) {
                                       std::lock_guard<std::mutex> lock(interrupt.mutex());
                                       log.append(r);
                                       ++finished;
                                       progress.trial_done(r);
                                     },
                                     range, std::move(resumed.finished)});
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
  cmd->add_option("--columns", o->columns,
                  "data columns holding t, u, y (and segment), e.g. t=t_s,u=u_N,y=y_m");
  cmd->add_option("--trial-range", o->trial_range,
                  "run only trials FROM to TO-1 (0-based, e.g. 0:5) of the experiment, with the "
                  "seeds they have in the full run; merge slices with `hystbench report`");
  add_reference_option(*cmd, o->reference);
  cmd->add_flag("--force", o->force, "replace results already in the --out folder");
  cmd->add_flag("--resume", o->resume,
                "keep the finished trials in the --out folder (after Ctrl-C or a crash) and run "
                "only the missing ones");
  auto load_plugins = add_plugin_option(*cmd);
  return [o, load_plugins] {
    load_plugins();
    run(*o);
  };
}

}  // namespace hystbench::cli
