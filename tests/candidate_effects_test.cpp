// Which effects a diagnosis tries.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "framework/discovery/diagnosis.hpp"
#include "framework/model/model.hpp"

namespace hystbench {
namespace {

bool tries(const std::vector<std::string>& candidates, const std::string& effect) {
  return std::find(candidates.begin(), candidates.end(), effect) != candidates.end();
}

TEST(CandidateEffects, ByDefaultEveryEffectTheModelLacks) {
  const auto c = candidate_effects(Model::parse("hysteresis,msd"), DiagnoseOptions{});
  EXPECT_FALSE(tries(c, "hysteresis"));
  EXPECT_FALSE(tries(c, "msd"));
  for (const char* effect : {"duffing", "feedback_hysteresis", "offset", "second_mode", "arx"})
    EXPECT_TRUE(tries(c, effect)) << effect << ": those that extend msd replace it";
}

// Once an extension of msd holds the resonance, neither msd nor another
// extension is offered: either would go in series as a second resonance.
TEST(CandidateEffects, NotAnEffectWhoseRoleTheModelAlreadyHolds) {
  const auto c = candidate_effects(Model::parse("duffing,offset"), DiagnoseOptions{});
  EXPECT_FALSE(tries(c, "msd"));
  EXPECT_FALSE(tries(c, "feedback_hysteresis"));
  EXPECT_TRUE(tries(c, "second_mode"));
  EXPECT_TRUE(tries(c, "arx"));
  EXPECT_FALSE(tries(candidate_effects(Model::parse("feedback_hysteresis"), DiagnoseOptions{}), "duffing"));
}

TEST(CandidateEffects, NamedCandidatesAreTriedAsNamedLessExclusions) {
  DiagnoseOptions o;
  o.candidates = {"msd", "feedback_hysteresis", "offset", "duffing"};
  o.exclude = {"offset"};
  const std::vector<std::string> expected = {"msd", "feedback_hysteresis"};
  EXPECT_EQ(candidate_effects(Model::parse("duffing"), o), expected);
}

}  // namespace
}  // namespace hystbench
