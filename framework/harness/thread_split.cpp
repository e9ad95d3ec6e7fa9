#include "framework/harness/thread_split.hpp"

#include <algorithm>

namespace hystbench {

ThreadSplit split_threads(long tasks, int threads) {
  threads = std::max(threads, 1);
  if (tasks >= threads) return {threads, 1};
  return {1, threads};
}

}  // namespace hystbench
