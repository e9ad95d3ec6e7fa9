#include "benchmarks/peer/pagmo_algorithm_factory.hpp"

#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/de1220.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <stdexcept>

namespace hystbench::peer {
namespace {

// pagmo's DE family stops once the population's spread in f or x falls
// below a tolerance; zero switches that off so every run spends the same
// budget, as ours do.
constexpr double kNoTolerance = 0.0;

}  // namespace

pagmo::algorithm make_pagmo_algorithm(const PagmoRun& run) {
  const unsigned gen = run.generations;
  const unsigned seed = run.seed;
  const std::string& name = run.algorithm;
  // Positional arguments other than gen, tolerances and seed are pagmo's defaults.
  if (name == "de") return pagmo::algorithm{pagmo::de(gen, 0.8, 0.9, 2u, kNoTolerance, kNoTolerance, seed)};
  if (name == "sade")
    return pagmo::algorithm{pagmo::sade(gen, 2u, 1u, kNoTolerance, kNoTolerance, false, seed)};
  if (name == "de1220")
    return pagmo::algorithm{pagmo::de1220(gen, pagmo::de1220_statics<void>::allowed_variants, 1u,
                                          kNoTolerance, kNoTolerance, false, seed)};
  if (name == "pso")
    return pagmo::algorithm{pagmo::pso(gen, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed)};
  if (name == "sga")
    return pagmo::algorithm{pagmo::sga(gen, .9, 1., .02, 1., 2u, "exponential", "polynomial",
                                       "tournament", seed)};
  if (name == "sga-sbx") {
    if (run.dimension == 0) throw std::invalid_argument("sga-sbx needs the problem's dimension");
    return pagmo::algorithm{pagmo::sga(gen, .9, 20., 1. / run.dimension, 20., 2u, "sbx",
                                       "polynomial", "tournament", seed)};
  }
  // force_bounds: our problem's box is part of the problem, as in our CMA-ES.
  if (name == "cmaes")
    return pagmo::algorithm{pagmo::cmaes(gen, -1, -1, -1, -1, 0.5, kNoTolerance, kNoTolerance, false,
                                         true, seed)};
  throw std::invalid_argument("unknown pagmo algorithm \"" + name +
                              "\"; known: de, sade, de1220, pso, sga, sga-sbx, cmaes");
}

}  // namespace hystbench::peer
