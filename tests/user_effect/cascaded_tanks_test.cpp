// The cascaded tanks example effect (examples/cascaded_tanks_effect), built
// into this program as a plugin registers it: it passes the signal through
// at its neutral values, is a first-order lag with linear outflow, settles
// at Torricelli's level, overflows into the lower tank, and its sensor clips
// the level it reads without touching the level itself.
#include "examples/cascaded_tanks_effect/cascaded_tanks.cpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace hystbench {
namespace {

// p = (log10 tau1, log10 tau2, alpha1, alpha2, inv_capacity, spill, inv_ceiling), sampled every `ts` s.
Eigen::VectorXd tanks(const std::array<double, 7>& p, Eigen::VectorXd w, double ts = 1.0) {
  const auto effect = EffectRegistry::instance().find("cascaded_tanks", "effect").create();
  SignalContext ctx;
  ctx.sample_time = ts;
  EXPECT_TRUE(effect->apply(p, ctx, w));
  return w;
}

TEST(CascadedTanksExample, AtItsNeutralValuesTheSignalPassesThroughExactly) {
  Eigen::VectorXd w(200);
  for (Eigen::Index k = 0; k < w.size(); ++k) w[k] = 1.5 * std::sin(0.1 * double(k)) - 0.2;
  EXPECT_EQ(tanks({-1.0, -1.0, 1.0, 1.0, 0.0, 0.0, 0.0}, w), w);
}

TEST(CascadedTanksExample, ALowerTankWithLinearOutflowIsAFirstOrderLag) {
  // tau·h' = 1 − h from h = 0: h(t) = 1 − exp(−t/tau). RK4's error at 4
  // steps of 0.25 s on tau = 5 s is below 1e-7.
  const Eigen::VectorXd y = tanks({-1.0, std::log10(5.0), 1.0, 1.0, 0.0, 0.0, 0.0}, Eigen::VectorXd::Ones(30));
  for (Eigen::Index k = 0; k < y.size(); ++k) EXPECT_NEAR(y[k], 1.0 - std::exp(-double(k) / 5.0), 1e-7) << k;
}

TEST(CascadedTanksExample, TorricelliTanksSettleAtTheSquareOfTheirInflow) {
  // In steady state each tank passes its inflow: sqrt(h) = w.
  const Eigen::VectorXd y = tanks({std::log10(4.0), std::log10(6.0), 0.5, 0.5, 0.0, 0.0, 0.0},
                                  Eigen::VectorXd::Constant(400, 0.7));
  EXPECT_NEAR(y[y.size() - 1], 0.49, 1e-9);
  EXPECT_LT(y[10], 0.49);
}

TEST(CascadedTanksExample, TheLowerTanksExponentAloneShapesTheSteadyLevel) {
  // The upper tank passes its inflow whatever its exponent; the lower one
  // settles where h2^(1/4) = w: 1.2^4.
  const Eigen::VectorXd y = tanks({std::log10(4.0), std::log10(6.0), 0.5, 0.25, 0.0, 0.0, 0.0},
                                  Eigen::VectorXd::Constant(2000, 1.2));
  EXPECT_NEAR(y[y.size() - 1], 2.0736, 1e-9);
  // With the upper tank gone, the lower one's level is the same power.
  const Eigen::VectorXd one = tanks({-1.0, std::log10(6.0), 0.5, 0.25, 0.0, 0.0, 0.0},
                                    Eigen::VectorXd::Constant(2000, 1.2));
  EXPECT_NEAR(one[one.size() - 1], 2.0736, 1e-9);
}

TEST(CascadedTanksExample, AFullUpperTankSpillsItsShareOfTheExcessIntoTheLowerOne) {
  // Capacity 1/4 passes sqrt(1/4) = 1/2 of the inflow 1; a quarter of the
  // other half spills below: the lower tank settles at (1/2 + 1/8)².
  const Eigen::VectorXd y = tanks({std::log10(2.0), std::log10(3.0), 0.5, 0.5, 4.0, 0.25, 0.0},
                                  Eigen::VectorXd::Ones(400));
  EXPECT_NEAR(y[y.size() - 1], 0.625 * 0.625, 1e-9);
  // Without the spill the overflow is lost.
  const Eigen::VectorXd lost = tanks({std::log10(2.0), std::log10(3.0), 0.5, 0.5, 4.0, 0.0, 0.0},
                                     Eigen::VectorXd::Ones(400));
  EXPECT_NEAR(lost[lost.size() - 1], 0.25, 1e-9);
}

TEST(CascadedTanksExample, TheSensorClipsTheLevelItReadsButNotTheLevel) {
  // Ceiling 1.5 on a level that rises above it and falls back: the reading
  // is the unclipped level wherever that is below 1.5, also after a clip.
  Eigen::VectorXd w(300);
  for (Eigen::Index k = 0; k < w.size(); ++k) w[k] = 1.0 + 0.8 * std::sin(2.0 * std::numbers::pi * double(k) / 100.0);
  const Eigen::VectorXd level = tanks({std::log10(3.0), std::log10(5.0), 0.5, 0.5, 0.0, 0.0, 0.0}, w);
  const Eigen::VectorXd read = tanks({std::log10(3.0), std::log10(5.0), 0.5, 0.5, 0.0, 0.0, 1.0 / 1.5}, w);
  Eigen::Index clipped = 0, after = 0;
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    EXPECT_EQ(read[k], std::min(level[k], 1.5)) << k;
    clipped += level[k] > 1.5;
    after += clipped > 0 && level[k] < 1.5;
  }
  EXPECT_GT(clipped, 10);
  EXPECT_GT(after, 10);
}

TEST(CascadedTanksExample, ATimeScaleBelowItsBoxIsRejected) {
  const auto effect = EffectRegistry::instance().find("cascaded_tanks", "effect").create();
  SignalContext ctx;
  ctx.sample_time = 1.0;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(10);
  EXPECT_FALSE(effect->apply(std::array<double, 7>{-1.5, 0.0, 0.5, 0.5, 0.0, 0.0, 0.0}, ctx, w));
}

}  // namespace
}  // namespace hystbench
