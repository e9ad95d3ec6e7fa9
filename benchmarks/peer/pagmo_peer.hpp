#pragma once
// The pagmo side of the peer comparison, behind plain types. It lives in its
// own shared library with hidden symbols: its translation units include
// pagmo's headers with Eigen configured like the Debian library (16-byte
// alignment, no -march=native), and hiding keeps those Eigen instantiations
// from being merged with ours.
#include <string>
#include <vector>

#include "benchmarks/peer/box_fitness.hpp"
#include "benchmarks/peer/peer_trial.hpp"

#define HYSTBENCH_PEER_API __attribute__((visibility("default")))

namespace hystbench::peer {

// One seeded run of a pagmo algorithm: "de", "sade", "de1220", "pso", "sga"
// or "cmaes", with pagmo's default settings except that the tolerance stops
// are off (the run spends its generations) and CMA-ES keeps to the box;
// "sga-sbx" is sga with our GA's default operators (SBX eta 20, polynomial
// mutation eta 20 at rate 1 / dimension, binary tournament).
struct PagmoRun {
  std::string algorithm;
  unsigned population = 0;
  unsigned generations = 0;
  unsigned seed = 0;
  unsigned dimension = 0;  // needed by "sga-sbx" only
};

// Throws std::invalid_argument for an unknown algorithm name.
HYSTBENCH_PEER_API PeerTrial run_pagmo(const BoxFitness& problem, const PagmoRun& run);

// The same runs on pagmo archipelagos of `islands` thread islands (one run
// per island, no migration), one archipelago after another: pagmo's own way
// to use several cores, with no more threads than the machine has (one
// island per run would start one thread per run). Returns the wall time of
// the whole set, population initialisation included.
HYSTBENCH_PEER_API double run_pagmo_archipelago(const BoxFitness& problem,
                                                const std::vector<PagmoRun>& runs,
                                                unsigned islands);

// Fitness of x through the pagmo problem wrapper (one candidate per call),
// and of candidates one after another through its batch_fitness.
HYSTBENCH_PEER_API double pagmo_fitness(const BoxFitness& problem, const std::vector<double>& x);
HYSTBENCH_PEER_API std::vector<double> pagmo_batch_fitness(const BoxFitness& problem,
                                                           const std::vector<double>& xs);

// `run` on a fitness that costs almost nothing (sum of squares in
// `dimension` variables on [-5, 5]): its time is pagmo's own.
HYSTBENCH_PEER_API PeerTrial run_pagmo_on_trivial(const PagmoRun& run, unsigned dimension);

HYSTBENCH_PEER_API std::string pagmo_version();

}  // namespace hystbench::peer
