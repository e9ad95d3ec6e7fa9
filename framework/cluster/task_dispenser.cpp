#include "framework/cluster/task_dispenser.hpp"

#include <algorithm>

namespace hystbench::cluster {

TaskDispenser::TaskDispenser(int algorithms, TrialRange trials)
    : trials_(trials),
      skipped_(algorithms, std::vector<bool>(std::max(0L, trials.size()), false)),
      next_(trials.first) {}

void TaskDispenser::skip(int algorithm, long trial) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (algorithm >= 0 && algorithm < int(skipped_.size()) && trial >= trials_.first &&
      trial < trials_.end)
    skipped_[algorithm][trial - trials_.first] = true;
}

bool TaskDispenser::pending(int algorithm, long trial) const {
  return trial < trials_.end && !skipped_[algorithm][trial - trials_.first];
}

TrialChunk TaskDispenser::take(long capacity) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (stopped_) return {};
  // Move to the next trial to hand out, algorithm by algorithm.
  while (algorithm_ < int(skipped_.size()) && !pending(algorithm_, next_)) {
    if (++next_ >= trials_.end) {
      ++algorithm_;
      next_ = trials_.first;
    }
  }
  if (algorithm_ >= int(skipped_.size())) return {};
  TrialChunk chunk{algorithm_, {next_, next_}};
  while (chunk.trials.size() < std::max(1L, capacity) && pending(algorithm_, chunk.trials.end))
    ++chunk.trials.end;
  next_ = chunk.trials.end;
  return chunk;
}

void TaskDispenser::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
}

}  // namespace hystbench::cluster
