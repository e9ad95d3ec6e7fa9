#pragma once
// The unit of work a rank is handed: consecutive trials of one algorithm.
// Trial k of an algorithm has the seed it has in a single-process run
// whichever rank runs it, so chunks change where trials run, never results.
#include <functional>

#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench::cluster {

struct TrialChunk {
  int algorithm = 0;  // index in the experiment's algorithm list
  TrialRange trials;  // empty: nothing left, stop
  bool empty() const { return trials.size() <= 0; }
};

// Runs the chunk with `threads` threads through run_campaign, so that a rank
// spends its threads exactly as a single-process run does. Calls
// on_trial_done once per finished trial, one call at a time.
void run_chunk(const Problem& problem, const Experiment& experiment, const TrialChunk& chunk,
               int threads, const std::function<void(const TrialResult&)>& on_trial_done);

}  // namespace hystbench::cluster
