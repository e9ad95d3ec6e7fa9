#include "benchmarks/peer/equal_budget.hpp"

#include <cmath>
#include <string>

#include "benchmarks/peer/hystbench_runs.hpp"
#include "benchmarks/peer/pagmo_peer.hpp"
#include "benchmarks/peer/problem_fitness.hpp"

namespace hystbench::peer {
namespace {

// Each framework at its defaults, with the same population where both have
// one. CMA-ES: pagmo's population is lambda, set to our default 4 + 3 ln n.
struct Pairing {
  std::string ours;
  nlohmann::json params;
  std::string our_settings;
  std::string theirs;
  unsigned population;
  std::string their_settings;
};

std::vector<Pairing> lineup(int dimension) {
  const auto lambda = static_cast<unsigned>(4 + std::floor(3.0 * std::log(dimension)));
  const std::string l = std::to_string(lambda);
  return {{"de", {{"np", 50}}, "NP 50, rand/1/bin, F 0.5, CR 0.9", "de", 50,
           "NP 50, rand/1/exp, F 0.8, CR 0.9"},
          {"mede", {{"np", 50}}, "NP 50", "sade", 50, "NP 50, rand/1/exp, jDE adaptation"},
          {"pso", {{"swarm", 40}}, "40 particles, inertia, gbest", "pso", 40,
           "40 particles, constriction (variant 5), lbest ring of 4"},
          {"cmaes", nlohmann::json::object(), "lambda " + l + ", IPOP restarts", "cmaes", lambda,
           "lambda " + l + ", no restarts, force_bounds"}};
}

Experiment our_experiment(const PeerSetup& setup, const std::vector<Pairing>& pairs) {
  nlohmann::json algorithms = nlohmann::json::array();
  for (const Pairing& p : pairs) algorithms.push_back({{"name", p.ours}, {"params", p.params}});
  return Experiment::from_json({{"name", "peer_equal_budget"},
                                {"problem", setup.problem_spec},
                                {"budget", {{"evaluations", setup.budget}}},
                                {"trials", setup.trials},
                                {"seed", setup.seed},
                                {"algorithms", algorithms}},
                               "equal-budget experiment");
}

PagmoRun pagmo_run(const PeerSetup& setup, const Pairing& p, long trial) {
  // Initial population plus whole generations, never above the budget.
  const auto generations = static_cast<unsigned>((setup.budget - p.population) / p.population);
  return {p.theirs, p.population, generations, static_cast<unsigned>(setup.seed + trial)};
}

}  // namespace

std::vector<PeerRow> equal_budget_rows(const PeerSetup& setup) {
  const auto pairs = lineup(setup.problem->dimension());
  const Experiment experiment = our_experiment(setup, pairs);
  const BoxFitness box = box_fitness(*setup.problem);
  const std::string budget = std::to_string(setup.budget) + " evaluations";
  std::vector<PeerRow> rows;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pairing& p = pairs[i];
    std::vector<PeerTrial> ours, theirs;
    for (long t = 0; t < setup.trials; ++t) {
      ours.push_back(run_hystbench_trial(*setup.problem, experiment, static_cast<int>(i), t));
      theirs.push_back(run_pagmo(box, pagmo_run(setup, p, t)));
    }
    rows.push_back(summarise({"equal budget", "hystbench", p.ours, p.our_settings, budget}, ours,
                             setup.noise_floor));
    rows.push_back(summarise({"equal budget", "pagmo", p.theirs, p.their_settings, budget}, theirs,
                             setup.noise_floor));
  }
  return rows;
}

}  // namespace hystbench::peer
