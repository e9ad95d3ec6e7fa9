// Polish: the last fraction of the budget goes to an NLopt local search from
// the best point, inside the same budget and trace.
#include <gtest/gtest.h>

#include "framework/core/error.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_runner.hpp"
#include "problems/functions/function_problem.hpp"

namespace hystbench {
namespace {

Experiment experiment(long evaluations, const nlohmann::json& polish) {
  nlohmann::json algorithm = {{"name", "de"}, {"params", {{"np", 20}}}};
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
}

}  // namespace
}  // namespace hystbench
