#pragma once
// Part 3: what each framework spends of its own per evaluation, measured on a
// fitness that costs almost nothing (sphere / sum of squares).
#include <vector>

#include "benchmarks/peer/peer_row.hpp"

namespace hystbench::peer {

std::vector<PeerRow> overhead_rows(int dimension, long evaluations, long trials, std::uint64_t seed);

}  // namespace hystbench::peer
