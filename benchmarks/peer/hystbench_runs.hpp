#pragma once
// The hystbench side: an experiment run through our own harness.
#include <vector>

#include "benchmarks/peer/peer_trial.hpp"
#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"

namespace hystbench::peer {

struct CampaignRun {
  std::vector<std::vector<PeerTrial>> trials;  // per algorithm, in trial order
  double wall_seconds = 0.0;                   // the whole campaign
};

// Every trial of every algorithm of `experiment`, `threads` trials at a time,
// exactly as `hystbench run` does it.
CampaignRun run_hystbench(const Problem& problem, const Experiment& experiment, int threads);

// One trial, with the seed it has in the whole campaign: lets a caller
// alternate our trials with pagmo's, so that a change in the machine's load
// falls on both alike.
PeerTrial run_hystbench_trial(const Problem& problem, const Experiment& experiment, int algorithm,
                              long trial);

}  // namespace hystbench::peer
