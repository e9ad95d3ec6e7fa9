// Failures are data: an optimizer that throws, or a trial in which no
// candidate had a finite fitness, is a failed trial carrying its message.
// The campaign goes on, trials.jsonl keeps the message, the results table
// counts the failures, and the statistics rank failed trials last and never
// count them as successes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/core/registry.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_log.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/report/trial_statistics.hpp"
#include "problems/functions/function_problem.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

CampaignOptions options(int threads, TrialRange trials,
                        std::function<void(const TrialResult&)> on_trial_done = nullptr) {
  CampaignOptions o;
  o.threads = threads;
  o.trials = trials;
  o.on_trial_done = std::move(on_trial_done);
  return o;
}
using test_support::contains;
using test_support::read;

// Random search that gives up with an exception after a first batch of 50
// points: always, or (flaky) in the trials whose first random number is
// below one half. Test-only; registered by the tests that use it, so that
// the optimizer contract suite does not see it.
class ThrowingSearch : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"test_throwing_search", "random search that throws (test only)", "none",
            {ParamSpec::boolean("flaky", false, "throw in about half of the trials only")}};
  }
  explicit ThrowingSearch(const Params& p) : flaky_(p.boolean("flaky")) {}
  void run(EvaluationContext& ctx) override {
    const bool throws = !flaky_ || ctx.rng().uniform() < 0.5;
    do {
      Eigen::MatrixXd X(ctx.dimension(), 50);
      for (Eigen::Index i = 0; i < X.cols(); ++i)
        for (int d = 0; d < ctx.dimension(); ++d)
          X(d, i) = ctx.rng().uniform(ctx.bounds().lower[d], ctx.bounds().upper[d]);
      Eigen::VectorXd f;
      ctx.evaluate(X, f);
      if (throws) throw std::runtime_error("deliberate failure after 50 evaluations");
    } while (!ctx.stopped());
  }

 private:
  bool flaky_;
};

void register_throwing_search() {
  static const detail::PluginRegistration<OptimizerInfo, ThrowingSearch, Params> registration;
}

// Sphere whose every value is NaN: every candidate "diverges".
class NanEverywhere : public Problem {
 public:
  NanEverywhere() : sphere_("sphere", 2, -5, 5) {}
  std::string name() const override { return "nan everywhere"; }
  const Bounds& bounds() const override { return sphere_.bounds(); }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>&, Eigen::Ref<Eigen::VectorXd> f) const override {
    f.setConstant(std::numeric_limits<double>::quiet_NaN());
  }

 private:
  FunctionProblem sphere_;
};

Experiment experiment(const nlohmann::json& algorithms, long trials = 6) {
  register_throwing_search();
  return Experiment::from_json({{"name", "failures"},
                                {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", 2}}},
                                {"budget", {{"evaluations", 400}}},
                                {"trials", trials},
                                {"seed", 5},
                                {"algorithms", algorithms}},
                               "failures");
}

const nlohmann::json kDeAndThrowing = {
    {{"name", "de"}, {"label", "DE"}, {"params", {{"np", 10}}}},
    {{"name", "test_throwing_search"}, {"label", "Throws"}},
    {{"name", "test_throwing_search"}, {"label", "Flaky"}, {"params", {{"flaky", true}}}}};

TEST(FailedTrials, ThrowingOptimizerIsRecordedAndTheCampaignGoesOn) {
  const Experiment e = experiment(kDeAndThrowing);
  const FunctionProblem sphere("sphere", 2, -5.12, 5.12);
  const auto results = run_campaign(sphere, e, options(2, {0, 6}));
  ASSERT_EQ(results.size(), 3u);
  for (const auto& r : results[0]) EXPECT_FALSE(r.failed()) << r.message;
  for (const auto& r : results[1]) {
    EXPECT_TRUE(r.failed());
    EXPECT_EQ(r.message, "deliberate failure after 50 evaluations");
    EXPECT_EQ(r.evaluations, 50);
  }
  long flaky_failures = 0;
  for (const auto& r : results[2]) flaky_failures += r.failed();
  EXPECT_GT(flaky_failures, 0);
  EXPECT_LT(flaky_failures, 6);
}

TEST(FailedTrials, EveryCandidateDivergingIsAFailedTrialWithAMessage) {
  const Experiment e = experiment({{{"name", "de"}, {"params", {{"np", 10}}}}}, 2);
  const NanEverywhere problem;
  const auto results = run_campaign(problem, e, options(1, {0, 2}));
  for (const auto& r : results[0]) {
    EXPECT_TRUE(r.failed());
    EXPECT_EQ(r.evaluations, 400) << "the budget was still spent";
    EXPECT_TRUE(contains(r.message, "no candidate had a finite fitness")) << r.message;
  }
}

TEST(FailedTrials, MessageIsKeptInTrialsJsonl) {
  test_support::TempDir dir;
  const Experiment e = experiment(kDeAndThrowing, 2);
  const FunctionProblem sphere("sphere", 2, -5.12, 5.12);
  {
    TrialLog log(dir.path() / "trials.jsonl");
    run_campaign(sphere, e, options(1, {0, 2}, [&](const TrialResult& r) { log.append(r); }));
  }
  long failed = 0;
  for (const auto& r : read_trial_log(dir.path() / "trials.jsonl").trials)
    if (r.failed()) {
      ++failed;
      EXPECT_EQ(r.stop, StopReason::Failed);
      EXPECT_FALSE(r.message.empty());
    }
  EXPECT_GE(failed, 2);
  EXPECT_TRUE(contains(read(dir.path() / "trials.jsonl"), R"("message":"deliberate failure after 50 evaluations")"));
}

TEST(FailedTrials, TableCountsThemAndSummaryLeavesThemOut) {
  test_support::TempDir dir;
  const Experiment e = experiment(kDeAndThrowing);
  const FunctionProblem sphere("sphere", 2, -5.12, 5.12);
  const auto results = run_campaign(sphere, e, options(2, {0, 6}));
  const auto written = write_report(dir.path(), e, sphere, results, 2);
  EXPECT_EQ(written.summaries[1].failed, 6);
  EXPECT_TRUE(std::isnan(written.summaries[1].best)) << "no statistics from failed trials";
  const std::string table = read(dir.path() / "table.md");
  EXPECT_TRUE(contains(table, "| 6/6 |")) << table;
  EXPECT_TRUE(contains(table, "| 0/6 |")) << table;
  EXPECT_TRUE(contains(table, "deliberate failure after 50 evaluations")) << table;
}

TEST(FailedTrials, RankLastAndNeverCountAsSuccesses) {
  const Experiment e = experiment(kDeAndThrowing);
  const FunctionProblem sphere("sphere", 2, -5.12, 5.12);
  const auto results = run_campaign(sphere, e, options(2, {0, 6}));
  // Target 5 (as 1.01 x a noise floor): random search gets below it within
  // 50 points on the 2-d sphere almost surely; failed trials still must not
  // count as successes.
  const double target = 5.0;
  bool reached_target_before_failing = false;
  for (const auto& r : results[1]) reached_target_before_failing |= r.best <= target;
  ASSERT_TRUE(reached_target_before_failing);

  const auto s = campaign_statistics(e, results, "DE", target / 1.01);
  EXPECT_EQ(s.rows[0].successes, 6);
  EXPECT_EQ(s.rows[1].successes, 0);
  EXPECT_EQ(s.rows[1].trials, 6);
  EXPECT_TRUE(std::isinf(s.rows[1].ert));
  EXPECT_EQ(s.rows[1].mark, '+') << "six failures against six finite results: DE is better";
}

}  // namespace
}  // namespace hystbench
