// hystbench_peer: hystbench against pagmo2 on the same Hammerstein data, the
// same fitness code and the same evaluation budget. Writes peer.md and
// peer.csv. See results/performance/README.md.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <thread>

#include "benchmarks/peer/equal_budget.hpp"
#include "benchmarks/peer/ga_replacement.hpp"
#include "benchmarks/peer/overhead.hpp"
#include "benchmarks/peer/peer_report.hpp"
#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"

namespace {

using namespace hystbench;
using namespace hystbench::peer;

struct Options {
  std::string data = "problems/hammerstein/data/default.csv";
  long budget = 20000;
  long trials = 5;
  std::uint64_t seed = 1;
  std::string protocol = "benchmarks/experiments/mede_table1.json";
  bool skip_protocol = false;
  int threads = static_cast<int>(std::thread::hardware_concurrency());
  long overhead_evaluations = 200000;
  long ga_evaluations = 50000;
  long ga_trials = 30;
  std::string out = "results/performance";
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("--data", o.data, "Hammerstein data CSV (its truth file gives the noise floor)")
      ->capture_default_str();
  app.add_option("--budget", o.budget, "evaluations per trial, equal-budget part")
      ->capture_default_str()->check(CLI::Range(100L, 100000000L));
  app.add_option("--trials", o.trials, "seeded trials per algorithm, equal-budget part")
      ->capture_default_str()->check(CLI::Range(1L, 10000L));
  app.add_option("--seed", o.seed, "seed of the equal-budget part")->capture_default_str();
  app.add_option("--protocol", o.protocol, "experiment file of the MEDE Table 1 protocol")
      ->capture_default_str();
  app.add_flag("--skip-protocol", o.skip_protocol, "leave the MEDE Table 1 protocol out");
  app.add_option("--threads", o.threads, "threads of the parallel protocol runs")
      ->capture_default_str()->check(CLI::Range(1, 1024));
  app.add_option("--overhead-evaluations", o.overhead_evaluations,
                 "evaluations per trial on the trivial fitness")
      ->capture_default_str()->check(CLI::Range(1000L, 1000000000L));
  app.add_option("--ga-evaluations", o.ga_evaluations,
                 "evaluations per trial of the GA replacement part (sphere-10)")
      ->capture_default_str()->check(CLI::Range(1000L, 1000000000L));
  app.add_option("--ga-trials", o.ga_trials, "seeded trials per GA of that part")
      ->capture_default_str()->check(CLI::Range(1L, 10000L));
  app.add_option("--out", o.out, "folder for peer.md and peer.csv")->capture_default_str();
}

PeerSetup equal_budget_setup(const Options& o, const Problem& problem) {
  PeerSetup s;
  s.problem = &problem;
  s.problem_spec = {{"type", "hammerstein"}, {"data", o.data}};
  const auto floor = problem.describe().value("noise_floor_sse", nlohmann::json());
  if (!floor.is_number()) throw InputError(o.data + ": no truth file with noise_floor_sse beside it");
  s.noise_floor = floor.get<double>();
  s.budget = o.budget;
  s.trials = o.trials;
  s.seed = o.seed;
  return s;
}

void log(const std::string& what) { std::cerr << "hystbench_peer: " << what << std::endl; }

PeerReport compare(const Options& o, const std::string& command) {
  PeerReport report;
  report.machine = machine_info();
  report.command = command;
  report.load_before = load_average();
  const auto problem = make_problem({{"type", "hammerstein"}, {"data", o.data}}, ".");
  const PeerSetup setup = equal_budget_setup(o, *problem);
  report.noise_floor = setup.noise_floor;
  log("equal budget (" + std::to_string(o.budget) + " evaluations x " + std::to_string(o.trials) + " trials)");
  report.rows = equal_budget_rows(setup);
  if (!o.skip_protocol) {
    log("MEDE Table 1 protocol (" + o.protocol + ")");
    ProtocolComparison p = table1_protocol(Experiment::load(o.protocol), o.threads);
    report.rows.insert(report.rows.end(), p.rows.begin(), p.rows.end());
    report.protocol = p.times;
  }
  log("overhead on a trivial fitness");
  const auto overhead = overhead_rows(problem->dimension(), o.overhead_evaluations, 3, o.seed);
  report.rows.insert(report.rows.end(), overhead.begin(), overhead.end());
  log("GA replacement on sphere-10 (" + std::to_string(o.ga_evaluations) + " evaluations x " +
      std::to_string(o.ga_trials) + " trials)");
  const auto ga = ga_replacement_rows(o.ga_evaluations, o.ga_trials, o.seed);
  report.rows.insert(report.rows.end(), ga.begin(), ga.end());
  report.load_after = load_average();
  return report;
}

// The command line as typed, for the report: program name without its folder.
std::string command_line(int argc, char** argv) {
  std::string s = std::filesystem::path(argv[0]).filename().string();
  for (int i = 1; i < argc; ++i) s += std::string(" ") + argv[i];
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hystbench against pagmo2: same data, same fitness, same evaluation budget"};
  Options o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);
  try {
    const PeerReport report = compare(o, command_line(argc, argv));
    std::filesystem::create_directories(o.out);
    write_markdown(std::filesystem::path(o.out) / "peer.md", report);
    write_csv(std::filesystem::path(o.out) / "peer.csv", report.rows);
    log("wrote " + o.out + "/peer.md and peer.csv");
  } catch (const InputError& e) {
    std::cerr << "hystbench_peer: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
