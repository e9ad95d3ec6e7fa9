// Direct calls through the pagmo problem wrapper, for the equality test.
#include <pagmo/config.hpp>
#include <pagmo/problem.hpp>
#include <memory>

#include "benchmarks/peer/pagmo_peer.hpp"
#include "benchmarks/peer/pagmo_problem.hpp"

namespace hystbench::peer {

double pagmo_fitness(const BoxFitness& problem, const std::vector<double>& x) {
  const pagmo::problem p{PagmoProblem{std::make_shared<const BoxFitness>(problem)}};
  return p.fitness(x)[0];
}

std::vector<double> pagmo_batch_fitness(const BoxFitness& problem, const std::vector<double>& xs) {
  const pagmo::problem p{PagmoProblem{std::make_shared<const BoxFitness>(problem)}};
  return p.batch_fitness(xs);
}

std::string pagmo_version() { return PAGMO_VERSION; }

}  // namespace hystbench::peer
