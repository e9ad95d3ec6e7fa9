#pragma once
// Part 4: our GA's two replacement schemes beside pagmo's sga with the same
// operators, on sphere-10: what pooling parents and children buys.
#include <cstdint>
#include <vector>

#include "benchmarks/peer/peer_row.hpp"

namespace hystbench::peer {

std::vector<PeerRow> ga_replacement_rows(long evaluations, long trials, std::uint64_t seed);

}  // namespace hystbench::peer
