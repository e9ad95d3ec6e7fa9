#pragma once
// Part 2: the MEDE Table 1 protocol (benchmarks/experiments/mede_table1.json)
// through hystbench, against the closest pagmo protocol: for each of our
// algorithms the pagmo algorithm nearest to it, with the same population,
// generations and number of trials.
#include <vector>

#include "benchmarks/peer/peer_row.hpp"
#include "framework/harness/experiment.hpp"

namespace hystbench::peer {

struct ProtocolTimes {
  // One trial at a time, ours and pagmo's alternating: sums of trial times.
  double hystbench_serial = 0.0;
  double pagmo_serial = 0.0;
  // The whole protocol on `threads` cores, wall clock: our trials in
  // parallel, pagmo's on archipelagos of `threads` thread islands.
  double hystbench_parallel = 0.0;
  double pagmo_archipelago = 0.0;
  int threads = 1;
  long evaluations = 0;             // whole protocol, hystbench
  long pagmo_evaluations = 0;
};

struct ProtocolComparison {
  std::vector<PeerRow> rows;  // per framework and algorithm, serial runs
  ProtocolTimes times;
};

// Runs on the experiment's own problem, which must carry a noise floor.
ProtocolComparison table1_protocol(const Experiment& experiment, int threads);

}  // namespace hystbench::peer
