#pragma once
// Hands out a campaign's trials in chunks, first come first served, so that a
// rank that finishes early takes the next chunk. Thread-safe: rank 0's own
// trials and the ranks its message loop serves draw from the same one.
#include <mutex>
#include <vector>

#include "framework/cluster/trial_chunk.hpp"

namespace hystbench::cluster {

class TaskDispenser {
 public:
  TaskDispenser(int algorithms, TrialRange trials);
  // A trial not to hand out: finished by an earlier run (`run --resume`).
  void skip(int algorithm, long trial);
  // At most `capacity` consecutive trials of one algorithm, none of them
  // skipped; empty when none are left or after stop().
  TrialChunk take(long capacity);
  // Hands out nothing more (the run failed on rank 0).
  void stop();

 private:
  bool pending(int algorithm, long trial) const;

  std::mutex mutex_;
  TrialRange trials_;
  std::vector<std::vector<bool>> skipped_;
  int algorithm_ = 0;
  long next_;
  bool stopped_ = false;
};

}  // namespace hystbench::cluster
