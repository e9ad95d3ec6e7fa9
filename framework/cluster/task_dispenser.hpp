#pragma once
// Hands out a campaign's trials in chunks, first come first served, so that a
// rank that finishes early takes the next chunk. Thread-safe: rank 0's own
// trials and the ranks its message loop serves draw from the same one.
#include <mutex>

#include "framework/cluster/trial_chunk.hpp"

namespace hystbench::cluster {

class TaskDispenser {
 public:
  TaskDispenser(int algorithms, TrialRange trials);
  // At most `capacity` trials of one algorithm; empty when none are left or
  // after stop().
  TrialChunk take(long capacity);
  // Hands out nothing more (the run failed on rank 0).
  void stop();

 private:
  std::mutex mutex_;
  int algorithms_;
  TrialRange trials_;
  int algorithm_ = 0;
  long next_;
  bool stopped_ = false;
};

}  // namespace hystbench::cluster
