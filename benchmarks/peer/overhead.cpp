#include "benchmarks/peer/overhead.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "benchmarks/peer/hystbench_runs.hpp"
#include "benchmarks/peer/pagmo_peer.hpp"
#include "framework/core/registry.hpp"

namespace hystbench::peer {
namespace {

// Same populations as the equal-budget part; CMA-ES without restarts on both
// sides, since IPOP's growing population changes the cost per evaluation.
struct Pairing {
  std::string ours;
  nlohmann::json params;
  std::string theirs;
  unsigned population;
};

Experiment sphere_experiment(const std::vector<Pairing>& pairs, int dimension, long evaluations,
                             long trials, std::uint64_t seed) {
  nlohmann::json algorithms = nlohmann::json::array();
  for (const Pairing& p : pairs) algorithms.push_back({{"name", p.ours}, {"params", p.params}});
  return Experiment::from_json(
      {{"name", "peer_overhead"},
       {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", dimension}}},
       {"budget", {{"evaluations", evaluations}}},
       {"trials", trials},
       {"seed", seed},
       {"algorithms", algorithms}},
      "overhead experiment");
}

// The fitness ratio means nothing on the sphere; the table shows a dash.
PeerRow without_fitness(PeerRow row) {
  row.median_over_floor = row.best_over_floor = std::numeric_limits<double>::quiet_NaN();
  return row;
}

}  // namespace

std::vector<PeerRow> overhead_rows(int dimension, long evaluations, long trials, std::uint64_t seed) {
  const auto lambda = static_cast<unsigned>(4 + std::floor(3.0 * std::log(dimension)));
  const std::vector<Pairing> pairs = {{"de", {{"np", 50}}, "de", 50},
                                      {"pso", {{"swarm", 40}}, "pso", 40},
                                      {"cmaes", {{"restarts", "none"}}, "cmaes", lambda}};
  const Experiment e = sphere_experiment(pairs, dimension, evaluations, trials, seed);
  const auto problem = make_problem(e.problem, e.base_dir);
  const CampaignRun ours = run_hystbench(*problem, e, 1);
  const std::string budget = std::to_string(evaluations) + " evaluations";
  const std::string what = "sphere, " + std::to_string(dimension) + " variables";
  std::vector<PeerRow> rows;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pairing& p = pairs[i];
    rows.push_back(without_fitness(summarise({"overhead", "hystbench", p.ours, what, budget}, ours.trials[i], 1.0)));
    const auto generations = static_cast<unsigned>((evaluations - p.population) / p.population);
    std::vector<PeerTrial> theirs;
    for (long t = 0; t < trials; ++t)
      theirs.push_back(run_pagmo_on_trivial({p.theirs, p.population, generations,
                                             static_cast<unsigned>(seed + t)},
                                            static_cast<unsigned>(dimension)));
    rows.push_back(without_fitness(summarise({"overhead", "pagmo", p.theirs, what, budget}, theirs, 1.0)));
  }
  return rows;
}

}  // namespace hystbench::peer
