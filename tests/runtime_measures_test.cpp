#include "framework/stats/runtime_measures.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "framework/core/error.hpp"

namespace hystbench::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Four trials, target 1.0:
//   t1: reaches 1 at evaluation 200 of 1000   -> RT 200 (success)
//   t2: best 2 after 1000                      -> RT 1000 (failure)
//   t3: reaches 0.5 at evaluation 1 of 600     -> RT 1 (success)
//   t4: stops early at 500 with best 3         -> RT 500 (failure)
std::vector<TrialRecord> four_trials() {
  return {{1000, {{1, 10.0}, {50, 5.0}, {200, 1.0}, {800, 0.1}}},
          {1000, {{1, 8.0}, {400, 2.0}}},
          {600, {{1, 0.5}}},
          {500, {{1, 3.0}}}};
}

TEST(RuntimeMeasures, FirstHitIsTheFirstTracePointAtOrBelowTheTarget) {
  const auto t = four_trials();
  EXPECT_EQ(evaluations_to_target(t[0].trace, 1.0), 200);  // <= counts, not only <
  EXPECT_EQ(evaluations_to_target(t[0].trace, 6.0), 50);
  EXPECT_EQ(evaluations_to_target(t[0].trace, 0.01), std::nullopt);
  EXPECT_EQ(evaluations_to_target({}, 1.0), std::nullopt);
  EXPECT_EQ(runtime_to_target(t[0], 1.0), 200);
  EXPECT_EQ(runtime_to_target(t[1], 1.0), 1000);
  EXPECT_THROW(evaluations_to_target(t[0].trace, std::nan("")), InputError);
}

// ERT = (200 + 1000 + 1 + 500) / 2 successes = 850.5; equivalently
// mean RT_s + (1 - p_s)/p_s mean RT_us = 100.5 + 1 * 750.
TEST(RuntimeMeasures, SuccessRateAndExpectedRuntime) {
  const auto t = four_trials();
  EXPECT_DOUBLE_EQ(success_rate(t, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(expected_runtime(t, 1.0), 850.5);
  // Target 5: t1 at 50, t2 at 400, t3 at 1, t4 at 1 -> all succeed.
  EXPECT_DOUBLE_EQ(success_rate(t, 5.0), 1.0);
  EXPECT_DOUBLE_EQ(expected_runtime(t, 5.0), (50.0 + 400 + 1 + 1) / 4);
}

TEST(RuntimeMeasures, ZeroSuccessesGiveInfiniteErtAndEmptyEcdf) {
  const auto t = four_trials();
  EXPECT_EQ(success_rate(t, 0.01), 0.0);
  EXPECT_EQ(expected_runtime(t, 0.01), kInf);
  EXPECT_TRUE(runtime_ecdf(t, 0.01).empty());
  EXPECT_THROW(expected_runtime({}, 1.0), InputError);
  EXPECT_THROW(success_rate({}, 1.0), InputError);
}

TEST(RuntimeMeasures, FailedTrialCostsItsLastTracedEvaluationIfLater) {
  const TrialRecord t{300, {{1, 9.0}, {450, 4.0}}};
  EXPECT_EQ(runtime_to_target(t, 1.0), 450);
  EXPECT_EQ(expected_runtime({t, {100, {{10, 0.5}}}}, 1.0), 460.0);
}

TEST(RuntimeMeasures, EcdfStepsAtDistinctRuntimesOverAllTrials) {
  const auto steps = runtime_ecdf(four_trials(), 1.0);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].evaluations, 1);
  EXPECT_DOUBLE_EQ(steps[0].fraction, 0.25);
  EXPECT_EQ(steps[1].evaluations, 200);
  EXPECT_DOUBLE_EQ(steps[1].fraction, 0.5);  // saturates below 1: two failures
}

// Targets {1, 5} over 4 trials = 8 pairs; solved at 200, 1 (target 1) and
// 50, 400, 1, 1 (target 5): sorted 1 1 1 50 200 400.
TEST(RuntimeMeasures, EcdfPoolsTrialTargetPairsAndMergesTies) {
  const auto steps = runtime_ecdf(four_trials(), std::vector<double>{1.0, 5.0});
  ASSERT_EQ(steps.size(), 4u);
  const std::vector<long> evals{1, 50, 200, 400};
  const std::vector<double> fractions{3.0 / 8, 4.0 / 8, 5.0 / 8, 6.0 / 8};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(steps[i].evaluations, evals[i]) << i;
    EXPECT_DOUBLE_EQ(steps[i].fraction, fractions[i]) << i;
  }
  EXPECT_THROW(runtime_ecdf(four_trials(), std::vector<double>{}), InputError);
}

// Budget 1000: 0.0005 -> 0 evaluations (nothing yet), 0.1 -> 100 (point at
// 50), 0.5 -> 500 (point at 200), 1.0 -> 1000 (point at 800).
TEST(RuntimeMeasures, FixedBudgetSnapshotsTakeTheLastPointWithinTheBudget) {
  const auto trace = four_trials()[0].trace;
  const auto s = fixed_budget_snapshots(trace, 1000, {0.0005, 0.1, 0.5, 1.0});
  EXPECT_EQ(s, (std::vector<double>{kInf, 5.0, 1.0, 0.1}));
  EXPECT_EQ(best_at(trace, 199), 5.0);
  EXPECT_EQ(best_at(trace, 200), 1.0);  // a point exactly at the budget counts
  EXPECT_EQ(best_at({}, 1000), kInf);
}

TEST(RuntimeMeasures, SnapshotFractionRoundingKeepsTheIntendedEvaluation) {
  // 0.57 * 100 is 56.99999999999999 in binary; it means 57.
  const std::vector<TracePoint> trace{{10, 3.0}, {57, 2.0}, {58, 1.0}};
  EXPECT_EQ(fixed_budget_snapshots(trace, 100, {0.57}), (std::vector<double>{2.0}));
  EXPECT_THROW(fixed_budget_snapshots(trace, 0, {0.5}), InputError);
  EXPECT_THROW(fixed_budget_snapshots(trace, 100, {-0.1}), InputError);
  EXPECT_THROW(fixed_budget_snapshots(trace, 100, {kInf}), InputError);
}

}  // namespace
}  // namespace hystbench::stats
