// One level of parallelism at a time: trials, or the candidates inside an
// evaluation, and the harness tells the problem which.
#include <gtest/gtest.h>

#include <atomic>

#include "framework/harness/campaign.hpp"
#include "framework/harness/thread_split.hpp"
#include "problems/functions/function_problem.hpp"

namespace hystbench {
namespace {

TEST(ThreadSplit, EnoughTrialsRunInParallelWithSingleThreadedEvaluations) {
  EXPECT_EQ(split_threads(2, 2).trial_threads, 2);
  EXPECT_EQ(split_threads(2, 2).evaluation_threads, 1);
  EXPECT_EQ(split_threads(30, 4).trial_threads, 4);
  EXPECT_EQ(split_threads(30, 4).evaluation_threads, 1);
}

TEST(ThreadSplit, FewerTrialsThanThreadsRunOneByOneWithThreadedEvaluations) {
  EXPECT_EQ(split_threads(1, 2).trial_threads, 1);
  EXPECT_EQ(split_threads(1, 2).evaluation_threads, 2);
  EXPECT_EQ(split_threads(3, 8).trial_threads, 1);
  EXPECT_EQ(split_threads(3, 8).evaluation_threads, 8);
}

TEST(ThreadSplit, NeverFewerThanOneThread) {
  EXPECT_EQ(split_threads(5, 0).trial_threads, 1);
  EXPECT_EQ(split_threads(5, 0).evaluation_threads, 1);
  EXPECT_EQ(split_threads(0, 1).evaluation_threads, 1);
}

// The sphere, remembering the largest thread count it was offered.
class ThreadProbe : public FunctionProblem {
 public:
  ThreadProbe() : FunctionProblem("sphere", 2) {}
  void evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f,
                     const EvaluationOptions& options) const override {
    int seen = most_threads.load();
    while (options.threads > seen && !most_threads.compare_exchange_weak(seen, options.threads)) {
    }
    evaluate(X, f);
  }
  mutable std::atomic<int> most_threads{0};
};

Experiment experiment(long trials) {
  return Experiment::from_json({{"name", "t"},
                                {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", 2}}},
                                {"budget", {{"evaluations", 200}}},
                                {"trials", trials},
                                {"seed", 3},
                                {"algorithms", {{{"name", "de"}}}}},
                               "test");
}

CampaignOptions two_threads() {
  CampaignOptions options;
  options.threads = 2;
  return options;
}

TEST(ThreadSplit, CampaignGivesItsThreadsToTheEvaluationsOfASingleTrial) {
  const ThreadProbe probe;
  run_campaign(probe, experiment(1), two_threads());
  EXPECT_EQ(probe.most_threads.load(), 2);
}

TEST(ThreadSplit, CampaignKeepsEvaluationsSingleThreadedWhenTrialsFillTheThreads) {
  const ThreadProbe probe;
  run_campaign(probe, experiment(4), two_threads());
  EXPECT_EQ(probe.most_threads.load(), 1);
}

}  // namespace
}  // namespace hystbench
