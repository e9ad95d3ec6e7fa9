// How a run over MPI ranks shares out trials and puts them back in order,
// without MPI: the dispenser and the collector rank 0 uses.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "framework/cluster/result_collector.hpp"
#include "framework/cluster/task_dispenser.hpp"

namespace {

using hystbench::TrialRange;
using hystbench::TrialResult;
using hystbench::cluster::ResultCollector;
using hystbench::cluster::TaskDispenser;
using hystbench::cluster::TrialChunk;

std::vector<TrialChunk> drain(TaskDispenser& d, long capacity) {
  std::vector<TrialChunk> chunks;
  for (TrialChunk c = d.take(capacity); !c.empty(); c = d.take(capacity)) chunks.push_back(c);
  return chunks;
}

TrialResult result(int algorithm, long trial) {
  TrialResult r;
  r.algorithm_index = algorithm;
  r.trial = trial;
  r.best = 10.0 * algorithm + double(trial);
  return r;
}

TEST(TaskDispenser, HandsOutEveryTrialOnceInChunksOfOneAlgorithm) {
  TaskDispenser d(2, {3, 8});
  const auto chunks = drain(d, 2);
  std::vector<std::vector<int>> seen(2, std::vector<int>(8, 0));
  for (const auto& c : chunks) {
    EXPECT_LE(c.trials.size(), 2);
    for (long t = c.trials.first; t < c.trials.end; ++t) ++seen[c.algorithm][t];
  }
  for (int a = 0; a < 2; ++a)
    for (long t = 0; t < 8; ++t) EXPECT_EQ(seen[a][t], t >= 3 ? 1 : 0) << a << " " << t;
  EXPECT_TRUE(d.take(2).empty());
}

TEST(TaskDispenser, SkipsFinishedTrialsAndChunksStopAtThem) {
  TaskDispenser d(2, {0, 5});
  d.skip(0, 2);
  for (long t = 0; t < 5; ++t) d.skip(1, t);
  const auto chunks = drain(d, 4);
  ASSERT_EQ(chunks.size(), 2u);
  EXPECT_EQ(chunks[0].algorithm, 0);
  EXPECT_EQ(chunks[0].trials.first, 0);
  EXPECT_EQ(chunks[0].trials.end, 2);
  EXPECT_EQ(chunks[1].trials.first, 3);
  EXPECT_EQ(chunks[1].trials.end, 5);
}

TEST(TaskDispenser, HandsOutNothingAfterStop) {
  TaskDispenser d(1, {0, 4});
  EXPECT_FALSE(d.take(1).empty());
  d.stop();
  EXPECT_TRUE(d.take(1).empty());
}

TEST(ResultCollector, PutsResultsInTrialOrderWhateverTheArrivalOrder) {
  int reported = 0;
  ResultCollector c(2, {1, 4}, [&](const TrialResult&) { ++reported; });
  for (auto [a, t] : std::vector<std::pair<int, long>>{{1, 3}, {0, 2}, {1, 1}, {0, 3}, {1, 2}}) c.add(result(a, t));
  c.keep(result(0, 1));  // finished by an earlier run: not reported again
  EXPECT_EQ(reported, 5);
  const auto results = c.take_results();
  ASSERT_EQ(results.size(), 2u);
  for (int a = 0; a < 2; ++a)
    for (long t = 1; t < 4; ++t) EXPECT_EQ(results[a][t - 1].best, 10.0 * a + double(t));
}

TEST(ResultCollector, ATrialSentTwiceIsAnError) {
  ResultCollector c(1, {0, 2}, nullptr);
  c.add(result(0, 1));
  c.add(result(0, 1));
  EXPECT_TRUE(c.failed());
  EXPECT_THROW(c.take_results(), std::runtime_error);
}

TEST(ResultCollector, KeepsTheCallbacksErrorAndStopsCallingIt) {
  int calls = 0;
  ResultCollector c(1, {0, 3}, [&](const TrialResult&) {
    ++calls;
    throw std::runtime_error("disk full");
  });
  c.add(result(0, 0));
  c.add(result(0, 1));
  EXPECT_EQ(calls, 1);
  EXPECT_THROW(c.take_results(), std::runtime_error);
}

}  // namespace
