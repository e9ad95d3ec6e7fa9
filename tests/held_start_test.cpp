// A record that starts where a held input left the system (held_start.hpp):
// the level is found from the warm-up, the simulation then matches a record
// made that way, the spec carries the choice, and it needs a warm-up.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.hpp"
#include "framework/model/held_start.hpp"
#include "framework/model/holdout.hpp"
#include "framework/model/model.hpp"
#include "framework/model/model_problem.hpp"

namespace hystbench {
namespace {

// 1 500 samples at 1 kHz: a 7 Hz sine about 0.8, so the input at t = 0 is
// far from where it was held before.
ModelData sine_record() {
  ModelData d;
  const Eigen::Index n = 1500;
  d.sample_time = 1e-3;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * double(n - 1));
  d.u = (0.8 + 0.3 * (2 * std::numbers::pi * 7.0 * d.t.array()).sin()).matrix();
  d.y = Eigen::VectorXd::Zero(n);
  d.estimation = Eigen::VectorXd::Ones(n);
  return d;
}

// gain 1.5, a resonance at 20 ms with ζ = 0.2: slow enough that a start at
// rest rings for many samples.
const Model& msd() {
  static const Model m = Model::parse("msd");
  return m;
}
Eigen::VectorXd msd_parameters() { return (Eigen::VectorXd(3) << 1.5, 0.02, 0.2).finished(); }

TEST(HeldStart, ARecordThatStartsFromAHeldLevelIsReproduced) {
  ModelData d = sine_record();
  const Eigen::VectorXd x = msd_parameters();
  // The "measurement": the same model after the input was held at 0.3.
  Eigen::VectorXd held_y;
  ASSERT_TRUE(msd().simulate(x, with_held_input(d, 0.3, kHeldStartSamples), held_y));
  d.y = held_y.tail(d.size());
  apply_holdout(d, HoldoutSpec::parse("none+warmup:10+held"));
  ASSERT_TRUE(d.held_start);
  double level = 0.0;
  ASSERT_TRUE(held_level(msd(), x, d, level));
  EXPECT_NEAR(level, 0.3, 1e-9);
  Eigen::VectorXd y;
  ASSERT_TRUE(msd().simulate(x, d, y));
  ASSERT_EQ(y.size(), d.size());
  EXPECT_LT((y - d.y).cwiseAbs().maxCoeff(), 1e-9);
  // From rest the same parameters miss the start: the output begins near
  // 0, not near 1.5 · 0.3 (plus the first sample's small direct feed).
  ModelData rest = d;
  rest.held_start = false;
  ASSERT_TRUE(msd().simulate(x, rest, y));
  EXPECT_NEAR(d.y[0], 0.45, 0.05);
  EXPECT_GT(std::abs(y[0] - d.y[0]), 0.4);
  // The fit's objective sees the held start, one candidate at a time.
  const ModelProblem problem(msd(), d);
  EXPECT_FALSE(problem.batched());
  EXPECT_LT(problem.sse(x), 1e-15);
}

TEST(HeldStart, TheLevelStopsAtTheNearerEndWhenNoneMatches) {
  // A measured level twice beyond the input's range and gain: the search
  // range ends at the record's range widened by half its span (1.4 here).
  ModelData d = sine_record();
  d.y.setConstant(10.0);
  apply_holdout(d, HoldoutSpec::parse("none+warmup:5+held"));
  double level = 0.0;
  ASSERT_TRUE(held_level(msd(), msd_parameters(), d, level));
  EXPECT_NEAR(level, d.u.maxCoeff() + 0.5 * (d.u.maxCoeff() - d.u.minCoeff()), 1e-12);
}

TEST(HeldStart, AConstantRecordIsMatchedAtItsOwnLevel) {
  // No span to search over: the range is still one unit wide about the input.
  ModelData d = sine_record();
  d.u.setConstant(0.7);
  d.y.setConstant(1.5 * 0.7);
  apply_holdout(d, HoldoutSpec::parse("none+warmup:3+held"));
  double level = 0.0;
  ASSERT_TRUE(held_level(msd(), msd_parameters(), d, level));
  EXPECT_NEAR(level, 0.7, 1e-9);
  Eigen::VectorXd y;
  ASSERT_TRUE(msd().simulate(msd_parameters(), d, y));
  EXPECT_LT((y - d.y).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(HeldStart, TheSpecCarriesItAndNeedsAWarmUp) {
  const HoldoutSpec s = HoldoutSpec::parse("auto+warmup:5+held");
  EXPECT_EQ(s.warmup, 5);
  EXPECT_TRUE(s.held_start);
  EXPECT_EQ(s.text(), "auto+warmup:5+held");
  EXPECT_FALSE(HoldoutSpec::parse("auto+warmup:5").held_start);
  ModelData d = sine_record();
  try {
    apply_holdout(d, HoldoutSpec::parse("auto+held"));
    FAIL() << "a held start without a warm-up was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give --warmup N"), std::string::npos) << e.what();
  }
  apply_holdout(d, s);
  EXPECT_NE(describe_holdout(d, s).find("--initial-state held"), std::string::npos);
}

}  // namespace
}  // namespace hystbench
