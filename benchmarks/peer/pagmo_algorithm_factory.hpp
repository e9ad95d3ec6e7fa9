#pragma once
// pagmo algorithm objects by name. Included only by the pagmo library.
#include <pagmo/algorithm.hpp>

#include "benchmarks/peer/pagmo_peer.hpp"

namespace hystbench::peer {

// Throws std::invalid_argument naming the known algorithms.
pagmo::algorithm make_pagmo_algorithm(const PagmoRun& run);

}  // namespace hystbench::peer
