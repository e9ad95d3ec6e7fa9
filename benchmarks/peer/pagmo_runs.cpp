// The pagmo runs, timed from problem construction to the evolved population.
#include <algorithm>
#include <chrono>
#include <memory>
#include <pagmo/archipelago.hpp>
#include <pagmo/islands/thread_island.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include "benchmarks/peer/pagmo_algorithm_factory.hpp"
#include "benchmarks/peer/pagmo_peer.hpp"
#include "benchmarks/peer/pagmo_problem.hpp"

namespace hystbench::peer {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

pagmo::problem wrap(const BoxFitness& box) {
  return pagmo::problem{PagmoProblem{std::make_shared<const BoxFitness>(box)}};
}

PeerTrial evolve_timed(const pagmo::problem& problem, const PagmoRun& run) {
  const auto start = Clock::now();
  pagmo::population pop{problem, run.population, run.seed};
  pop = make_pagmo_algorithm(run).evolve(pop);
  const double wall = seconds_since(start);
  return {pop.champion_f()[0], static_cast<long>(pop.get_problem().get_fevals()), wall};
}

}  // namespace

PeerTrial run_pagmo(const BoxFitness& problem, const PagmoRun& run) {
  return evolve_timed(wrap(problem), run);
}

double run_pagmo_archipelago(const BoxFitness& problem, const std::vector<PagmoRun>& runs,
                             unsigned islands) {
  const pagmo::problem wrapped = wrap(problem);
  const auto start = Clock::now();
  for (std::size_t first = 0; first < runs.size(); first += islands) {
    pagmo::archipelago archi;
    for (std::size_t i = first; i < std::min(runs.size(), first + islands); ++i)
      archi.push_back(pagmo::thread_island{}, make_pagmo_algorithm(runs[i]), wrapped,
                      runs[i].population, runs[i].seed);
    archi.evolve(1);
    archi.wait_check();
  }
  return seconds_since(start);
}

PeerTrial run_pagmo_on_trivial(const PagmoRun& run, unsigned dimension) {
  return evolve_timed(pagmo::problem{SumOfSquares{dimension}}, run);
}

}  // namespace hystbench::peer
