#pragma once
// Our Problem seen through the plain interface the pagmo side takes.
#include "benchmarks/peer/box_fitness.hpp"
#include "framework/core/problem.hpp"

namespace hystbench::peer {

// `problem` must outlive the result: the fitness calls problem.evaluate.
BoxFitness box_fitness(const Problem& problem);

}  // namespace hystbench::peer
