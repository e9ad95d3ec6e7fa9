#include "framework/cluster/task_dispenser.hpp"

#include <algorithm>

namespace hystbench::cluster {

TaskDispenser::TaskDispenser(int algorithms, TrialRange trials)
    : algorithms_(algorithms), trials_(trials), next_(trials.first) {}

TrialChunk TaskDispenser::take(long capacity) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (next_ >= trials_.end) {
    ++algorithm_;
    next_ = trials_.first;
  }
  if (stopped_ || algorithm_ >= algorithms_ || trials_.size() <= 0) return {};
  const long end = std::min(trials_.end, next_ + std::max(1L, capacity));
  TrialChunk chunk{algorithm_, {next_, end}};
  next_ = end;
  return chunk;
}

void TaskDispenser::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
}

}  // namespace hystbench::cluster
