#include "framework/core/parallel_jobs.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace hystbench {
namespace {

TEST(ParallelJobs, EveryJobRunsOnceAndFillsItsOwnSlot) {
  std::vector<int> out(37, 0);
  parallel_jobs(out.size(), [&](std::size_t i) { out[i] += int(i * i); });
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], int(i * i));
}

TEST(ParallelJobs, TheFirstFailureInJobOrderIsRethrownAfterAllJobsEnd) {
  const int before = omp_get_max_threads();
  for (int threads : {1, 2, 4}) {
    omp_set_num_threads(threads);
    std::vector<int> ran(10, 0);
    try {
      parallel_jobs(ran.size(), [&](std::size_t i) {
        ran[i] = 1;
        if (i == 3 || i == 7) throw std::runtime_error("job " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 3") << threads << " threads";
    }
    for (int r : ran) EXPECT_EQ(r, 1) << threads << " threads";
  }
  omp_set_num_threads(before);
}

TEST(ParallelJobs, NoJobsIsNothing) {
  int calls = 0;
  parallel_jobs(0, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace hystbench
