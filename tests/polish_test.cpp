// Polish: the last fraction of the budget goes to a local search (NLopt or
// Levenberg-Marquardt) from the best point, inside the same budget and trace.
#include <gtest/gtest.h>

#include "framework/core/error.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_runner.hpp"
#include "framework/io/measurement.hpp"
#include "problems/functions/function_problem.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace hystbench {
namespace {

Experiment experiment(long evaluations, const nlohmann::json& polish,
                      nlohmann::json algorithm = {{"name", "de"}, {"params", {{"np", 20}}}}) {
  if (!polish.is_null()) algorithm["polish"] = polish;
  return Experiment::from_json({{"name", "p"},
                                {"problem", {{"type", "function"}, {"name", "rosenbrock"}, {"dimension", 4}}},
                                {"budget", {{"evaluations", evaluations}}},
                                {"trials", 1},
                                {"seed", 4},
                                {"algorithms", {algorithm}}},
                               "test");
}

TEST(Polish, ContinuesExactlyWhereTheOptimizersShareOfTheBudgetEnds) {
  FunctionProblem rosenbrock("rosenbrock", 4);
  // The optimizer sees 80 % of 5000 as its whole budget, so its part of the
  // polished run is the plain run with 4000 evaluations, step for step.
  const auto plain = run_trial(rosenbrock, experiment(4000, nullptr), 0, 0);
  const auto polished =
      run_trial(rosenbrock, experiment(5000, {{"algorithm", "LN_BOBYQA"}, {"fraction", 0.2}}), 0, 0);
  ASSERT_FALSE(polished.failed()) << polished.message;
  EXPECT_EQ(polished.iterations, plain.iterations);
  EXPECT_GT(polished.evaluations, plain.evaluations);
  EXPECT_LE(polished.evaluations, 5000);
  EXPECT_LT(polished.best, plain.best * 1e-3);  // BOBYQA finishes what DE started
  // One trace: the polished run's trace starts as the plain one.
  ASSERT_GE(polished.trace.size(), plain.trace.size() - 1);
  for (std::size_t i = 0; i + 1 < plain.trace.size(); ++i) EXPECT_EQ(polished.trace[i].best, plain.trace[i].best);
}

TEST(Polish, NeedsALocalMethodAnEvaluationBudgetAndAFractionBelowOne) {
  const auto message = [](const nlohmann::json& polish, bool evaluations = true) {
    try {
      auto j = experiment(1000, polish).to_json();
      if (!evaluations) j["budget"] = {{"iterations", 10}};
      Experiment::from_json(j, "test");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{"algorithm", "GN_CRS2_LM"}}).find("use a local NLopt method"), std::string::npos);
  EXPECT_NE(message({{"fraction", 1.0}}).find("polish.fraction = 1.0: must be between 0 and 1"),
            std::string::npos);
  EXPECT_NE(message({{"fraction", 0.2}}, false).find("polish needs an evaluation budget"), std::string::npos);
  EXPECT_NE(message({{"repeat", "yes"}}).find("polish.repeat = \"yes\": must be true or false"), std::string::npos);
  EXPECT_EQ(message({{"algorithm", "levenberg_marquardt"}, {"repeat", true}}), "");
}

TEST(Polish, RepeatIsWrittenOnlyWhenSetSoOlderCampaignsKeepTheirIdentity) {
  const auto polish = [](const Experiment& e) { return e.to_json()["algorithms"][0]["polish"]; };
  EXPECT_FALSE(polish(experiment(1000, {{"fraction", 0.2}})).contains("repeat"));
  EXPECT_EQ(polish(experiment(1000, {{"fraction", 0.2}, {"repeat", true}}))["repeat"], true);
}

TEST(Polish, LevenbergMarquardtIsRefusedOnAProblemWithoutResiduals) {
  FunctionProblem sphere("sphere", 4);
  try {
    check_polish(experiment(1000, {{"algorithm", "levenberg_marquardt"}}), sphere);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("algorithms[0].polish.algorithm = \"levenberg_marquardt\" needs a least-squares problem"),
              std::string::npos) << m;
    EXPECT_NE(m.find("LN_BOBYQA"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(check_polish(experiment(1000, {{"algorithm", "LN_BOBYQA"}}), sphere));
}

TEST(Polish, RepeatRunsFreshCyclesUntilTheBudgetIsSpent) {
  // On Rastrigin, BOBYQA converges in a local minimum long before its 60 %
  // of the budget is spent. With repeat, the first cycle is the same run,
  // and the evaluations it leaves go to new cycles.
  FunctionProblem rastrigin("rastrigin", 4);
  const nlohmann::json once = {{"algorithm", "LN_BOBYQA"}, {"fraction", 0.6}};
  nlohmann::json repeated = once;
  repeated["repeat"] = true;
  const auto single = run_trial(rastrigin, experiment(6000, once), 0, 0);
  const auto cycles = run_trial(rastrigin, experiment(6000, repeated), 0, 0);
  ASSERT_FALSE(cycles.failed()) << cycles.message;
  EXPECT_LT(single.evaluations, 4000);
  EXPECT_GT(cycles.evaluations, 6000 - 2 * 4 - 2);
  EXPECT_LE(cycles.evaluations, 6000);
  EXPECT_LE(cycles.best, single.best);
  for (std::size_t i = 0; i + 1 < single.trace.size(); ++i) EXPECT_EQ(cycles.trace[i].best, single.trace[i].best);
  // Same seed, same cycles.
  const auto again = run_trial(rastrigin, experiment(6000, repeated), 0, 0);
  EXPECT_EQ(again.best, cycles.best);
  EXPECT_EQ(again.evaluations, cycles.evaluations);
}

TEST(Polish, CmaesWithRepeatedLevenbergMarquardtReachesTheNoiseFloorOfTheDefaultData) {
  // The time-to-quality configuration (benchmarks/experiments/time_to_quality.json)
  // on three of its seeds: each trial reaches 1.01 x the noise-floor SSE.
  const std::string csv = std::string(HYSTBENCH_SOURCE_DIR) + "/problems/hammerstein/data/default.csv";
  const HammersteinProblem problem(read_measurement(csv, {}), BoucWenForm::Increment,
                                   HammersteinProblem::default_bounds(), {}, 12044.95);
  auto j = experiment(10000, {{"algorithm", "levenberg_marquardt"}, {"fraction", 0.7}, {"repeat", true}},
                      {{"name", "cmaes"}})
               .to_json();
  j["budget"]["target"] = 1.01 * 12044.95;
  j["seed"] = 8000;
  const Experiment e = Experiment::from_json(j, "test");
  for (long trial = 0; trial < 3; ++trial) {
    const auto r = run_trial(problem, e, 0, trial);
    EXPECT_EQ(r.stop, StopReason::Target) << "trial " << trial << ": " << r.best << " after " << r.evaluations;
  }
}

}  // namespace
}  // namespace hystbench
