#include "benchmarks/peer/table1_protocol.hpp"

#include <map>
#include <string>

#include "benchmarks/peer/hystbench_runs.hpp"
#include "benchmarks/peer/pagmo_peer.hpp"
#include "benchmarks/peer/problem_fitness.hpp"
#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"

namespace hystbench::peer {
namespace {

// pagmo has no MEDE, DETVSF or real-coded GA of the papers. The nearest:
// sga for the GA, sade (self-adaptive F and CR) for DETVSF's varying F,
// de1220 (self-adaptive choice among DE strategies) for MEDE's ensemble.
std::string pagmo_counterpart(const std::string& plugin) {
  static const std::map<std::string, std::string> counterpart = {
      {"de", "de"}, {"ga", "sga"}, {"detvsf", "sade"}, {"mede", "de1220"}};
  const auto it = counterpart.find(plugin);
  if (it == counterpart.end())
    throw InputError("no pagmo counterpart for plugin \"" + plugin + "\"; known: de, ga, detvsf, mede");
  return it->second;
}

// Our populations: an explicit "np", or the DE family's auto value 10 x dimension.
unsigned population(const AlgorithmSpec& spec, int dimension) {
  const auto np = spec.params.value("np", nlohmann::json());
  return np.is_number_integer() ? np.get<unsigned>() : static_cast<unsigned>(10 * dimension);
}

std::vector<std::vector<PagmoRun>> pagmo_runs(const Experiment& e, int dimension) {
  if (!e.budget.iterations) throw InputError(e.name + ": the protocol needs budget.iterations");
  std::vector<std::vector<PagmoRun>> runs;
  for (const AlgorithmSpec& spec : e.algorithms) {
    auto& list = runs.emplace_back();
    for (long t = 0; t < e.trials; ++t)
      list.push_back({pagmo_counterpart(spec.name), population(spec, dimension),
                      static_cast<unsigned>(*e.budget.iterations), static_cast<unsigned>(e.seed + t)});
  }
  return runs;
}

void add_up(const std::vector<PeerTrial>& trials, double& seconds, long& evaluations) {
  for (const PeerTrial& t : trials) {
    seconds += t.wall_seconds;
    evaluations += t.evaluations;
  }
}

std::string settings(const PagmoRun& run) { return "NP " + std::to_string(run.population); }

}  // namespace

ProtocolComparison table1_protocol(const Experiment& e, int threads) {
  const auto problem = make_problem(e.problem, e.base_dir);
  const auto floor = problem->describe().value("noise_floor_sse", nlohmann::json());
  if (!floor.is_number()) throw InputError(e.name + ": the problem has no noise floor (truth file)");
  const double nf = floor.get<double>();
  const auto runs = pagmo_runs(e, problem->dimension());
  const BoxFitness box = box_fitness(*problem);
  const std::string budget = std::to_string(*e.budget.iterations) + " generations";

  ProtocolComparison out;
  ProtocolTimes& times = out.times;
  times.threads = threads;
  for (std::size_t a = 0; a < e.algorithms.size(); ++a) {
    const AlgorithmSpec& spec = e.algorithms[a];
    std::vector<PeerTrial> ours, theirs;
    for (long t = 0; t < e.trials; ++t) {
      ours.push_back(run_hystbench_trial(*problem, e, static_cast<int>(a), t));
      theirs.push_back(run_pagmo(box, runs[a][t]));
    }
    add_up(ours, times.hystbench_serial, times.evaluations);
    add_up(theirs, times.pagmo_serial, times.pagmo_evaluations);
    out.rows.push_back(summarise({"MEDE Table 1 protocol", "hystbench", spec.name,
                                  "NP " + std::to_string(population(spec, problem->dimension())), budget},
                                 ours, nf));
    out.rows.push_back(summarise({"MEDE Table 1 protocol", "pagmo", runs[a][0].algorithm,
                                  settings(runs[a][0]), budget},
                                 theirs, nf));
  }
  times.hystbench_parallel = run_hystbench(*problem, e, threads).wall_seconds;
  std::vector<PagmoRun> all;
  for (const auto& list : runs) all.insert(all.end(), list.begin(), list.end());
  times.pagmo_archipelago = run_pagmo_archipelago(box, all, static_cast<unsigned>(threads));
  return out;
}

}  // namespace hystbench::peer
