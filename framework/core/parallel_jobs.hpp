#pragma once
// Independent jobs run on OpenMP threads. An exception must not leave an
// OpenMP region, so each job's is caught and the first (in job order) is
// rethrown once every job has ended. Jobs write only their own slot of
// whatever they fill, so the results do not depend on the thread count.
#include <cstddef>
#include <exception>
#include <vector>

namespace hystbench {

template <class Job>
void parallel_jobs(std::size_t n, Job&& job) {
  std::vector<std::exception_ptr> failed(n);
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < n; ++i) {
    try {
      job(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  }
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace hystbench
