#pragma once
// Part 1: our de, mede, pso and cmaes against pagmo's de, sade, pso and
// cmaes, one trial at a time, at the same evaluation budget.
#include <vector>

#include "benchmarks/peer/peer_row.hpp"
#include "benchmarks/peer/peer_setup.hpp"

namespace hystbench::peer {

std::vector<PeerRow> equal_budget_rows(const PeerSetup& setup);

}  // namespace hystbench::peer
