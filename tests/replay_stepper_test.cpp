// The default streaming form of an effect (ReplayStepper): an effect that
// writes no stepper of its own, as an out-of-tree one may, streams exactly
// what its batch form gives, its stage input and time included.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "framework/model/replay_stepper.hpp"

namespace hystbench {
namespace {

// A stateful causal effect written only as apply(): a first-order lag of the
// stage input, weighted by p[0], plus p[1]·t.
class LaggedBranch : public Effect {
 public:
  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    if (!(p[0] < 10.0)) return false;
    double lag = 0.0;
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      lag += 0.1 * ((*ctx.stage_input)[k] - lag);
      signal[k] += p[0] * lag + p[1] * (*ctx.time)[k];
    }
    return true;
  }
};

TEST(ReplayStepper, IsTheDefaultAndStreamsExactlyWhatApplyGives) {
  const double ts = 1e-3;
  const Eigen::Index n = 500;
  Eigen::VectorXd signal(n), stage(n), t(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    t[k] = ts * double(k);
    stage[k] = std::sin(2.0 * std::numbers::pi * 7.0 * t[k]) + (k > 200 ? 0.5 : 0.0);
    signal[k] = 2.0 * stage[k] + 0.1 * std::cos(2.0 * std::numbers::pi * 31.0 * t[k]);
  }
  const LaggedBranch effect;
  const std::vector<double> p = {0.7, -0.3};
  Eigen::VectorXd batch = signal;
  ASSERT_TRUE(effect.apply(p, SignalContext{ts, &t, &stage, 0}, batch));

  const auto stepper = effect.stepper(p, StepContext{ts, InputHold::Linear, 0});
  ASSERT_NE(dynamic_cast<const ReplayStepper*>(stepper.get()), nullptr);
  for (Eigen::Index k = 0; k < n; ++k) ASSERT_EQ(stepper->step(signal[k], stage[k]), batch[k]) << "sample " << k;
  // Reset forgets the history; a clone keeps it.
  stepper->reset();
  for (Eigen::Index k = 0; k < 100; ++k) ASSERT_EQ(stepper->step(signal[k], stage[k]), batch[k]);
  const auto copy = stepper->clone();
  for (Eigen::Index k = 100; k < n; ++k) ASSERT_EQ(copy->step(signal[k], stage[k]), batch[k]) << "sample " << k;
}

TEST(ReplayStepper, ParametersApplyRefusesGiveNaN) {
  const LaggedBranch effect;
  const std::vector<double> p = {20.0, 0.0};
  const auto stepper = effect.stepper(p, StepContext{1e-3, InputHold::Linear, 0});
  EXPECT_TRUE(std::isnan(stepper->step(1.0, 1.0)));
}

}  // namespace
}  // namespace hystbench
