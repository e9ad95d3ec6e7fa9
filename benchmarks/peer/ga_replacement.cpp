#include "benchmarks/peer/ga_replacement.hpp"

#include <string>

#include "benchmarks/peer/hystbench_runs.hpp"
#include "benchmarks/peer/pagmo_peer.hpp"
#include "benchmarks/peer/problem_fitness.hpp"
#include "framework/core/registry.hpp"

namespace hystbench::peer {
namespace {

constexpr int kDimension = 10;
constexpr unsigned kPopulation = 100;

Experiment ga_experiment(long evaluations, long trials, std::uint64_t seed) {
  const nlohmann::json algorithms = {
      {{"name", "ga"}, {"label", "ga generational"}, {"params", {{"replacement", "generational"}}}},
      {{"name", "ga"}, {"label", "ga plus"}, {"params", {{"replacement", "plus"}}}}};
  return Experiment::from_json(
      {{"name", "peer_ga_replacement"},
       {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", kDimension}}},
       {"budget", {{"evaluations", evaluations}}},
       {"trials", trials},
       {"seed", seed},
       {"algorithms", algorithms}},
      "GA replacement experiment");
}

}  // namespace

// The fitness columns show the sphere's final value itself (floor 1): its
// optimum is 0, so there is no noise floor to divide by.
std::vector<PeerRow> ga_replacement_rows(long evaluations, long trials, std::uint64_t seed) {
  const Experiment e = ga_experiment(evaluations, trials, seed);
  const auto problem = make_problem(e.problem, e.base_dir);
  const BoxFitness box = box_fitness(*problem);
  const std::string budget = std::to_string(evaluations) + " evaluations";
  const std::string operators = ", SBX, binary tournament";
  const char* settings[] = {"NP 100, generational, 2 elites, polynomial mutation (NSGA-II form)",
                            "NP 100, plus (best N of parents and children), polynomial mutation (sga's form)"};
  std::vector<PeerRow> rows;
  std::vector<PeerTrial> theirs;
  std::vector<std::vector<PeerTrial>> ours(2);
  const auto generations = static_cast<unsigned>((evaluations - kPopulation) / kPopulation);
  for (long t = 0; t < trials; ++t) {
    for (int a = 0; a < 2; ++a) ours[a].push_back(run_hystbench_trial(*problem, e, a, t));
    theirs.push_back(run_pagmo(box, {"sga-sbx", kPopulation, generations,
                                     static_cast<unsigned>(seed + t), kDimension}));
  }
  for (int a = 0; a < 2; ++a)
    rows.push_back(summarise({"ga replacement", "hystbench", "ga", settings[a] + operators, budget},
                             ours[a], 1.0));
  rows.push_back(summarise({"ga replacement", "pagmo", "sga",
                            "NP 100, (mu + lambda) reinsertion, polynomial mutation" + operators, budget},
                           theirs, 1.0));
  return rows;
}

}  // namespace hystbench::peer
