// Every built-in effect has a batched form; a user's effect written with
// apply() alone (user_smoothing, user_effect_stream_test.cpp) has none, and
// a model containing it evaluates one candidate at a time, to the same values.
#include <gtest/gtest.h>

#include "framework/model/model.hpp"
#include "framework/model/model_problem.hpp"
#include "tests/lane_record.hpp"

namespace hystbench {
namespace {

TEST(UserEffectLanes, AModelWithAnEffectWithoutABatchedFormEvaluatesOneCandidateAtATime) {
  const Model model = Model::parse("hysteresis,msd,user_smoothing");
  const ModelData data = lane_record();
  const ModelProblem problem(model, data);
  EXPECT_FALSE(problem.batched());
  EXPECT_TRUE(ModelProblem(Model::parse("hysteresis,msd"), data).batched());
  const Eigen::MatrixXd X = lane_candidates(model, 5, 3);
  Eigen::VectorXd f(5);
  problem.evaluate(X, f);
  for (Eigen::Index j = 0; j < 5; ++j) EXPECT_EQ(f[j], problem.sse(X.col(j)));
}

}  // namespace
}  // namespace hystbench
