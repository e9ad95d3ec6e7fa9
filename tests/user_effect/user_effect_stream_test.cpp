// An effect registered the way a user's out-of-tree plugin registers one,
// with apply() alone and no stepper: a model containing it streams sample by
// sample through the default replay stepper and gives the batch output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "framework/model/model.hpp"
#include "framework/model/regressors.hpp"
#include "framework/model/streaming_model.hpp"

namespace {

hystbench::SignatureValue input_correlation(const hystbench::ResidualView& r) {
  return {hystbench::correlation(r.e, r.u)};
}

// Exponential smoothing y[k] = y[k-1] + a·(x[k] − y[k-1]) from rest; a = 1
// passes the signal through.
class UserSmoothing : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "user_smoothing";
    i.summary = "exponential smoothing of the dynamics' output";
    i.citation = "a test effect";
    i.stage = hystbench::EffectStage::Output;
    i.params = {{"a", 0.01, 1.0, 1.0, 0, 0, "", "smoothing weight (1 = none)"}};
    i.signature = "the residual follows the input";
    i.statistic = {"corr(e, u)", input_correlation, "the residual correlates with u (r = {value})"};
    return i;
  }
  bool apply(std::span<const double> p, const hystbench::SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    if (!(p[0] > 0.0 && p[0] <= 1.0)) return false;
    double y = 0.0;
    for (Eigen::Index k = 0; k < signal.size(); ++k) signal[k] = y += p[0] * (signal[k] - y);
    return true;
  }
};

}  // namespace

HYSTBENCH_EFFECT(UserSmoothing)

namespace hystbench {
namespace {

TEST(UserEffectStream, AnEffectWithoutAStepperStreamsLikeTheBatchSimulation) {
  // rectified_drive (user_effect_signature_test.cpp) and user_smoothing have
  // no stepper; the catalog effects around them do.
  const Model model = Model::parse("rectified_drive,hysteresis,msd,user_smoothing");
  Eigen::VectorXd x = model.neutral();
  const auto names = model.parameter_names();
  const std::vector<std::pair<std::string, double>> values = {
      {"rectified_drive.k", 0.4}, {"hysteresis.A", 0.5}, {"msd.period", 0.02},
      {"msd.zeta", 0.2},          {"user_smoothing.a", 0.3}};
  for (const auto& [name, value] : values)
    x[std::find(names.begin(), names.end(), name) - names.begin()] = value;
  ModelData d;
  const Eigen::Index n = 800;
  d.sample_time = 1e-3;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * double(n - 1));
  d.u = (2.0 * std::numbers::pi * 9.0 * d.t.array()).sin().matrix();
  Model linear = model;
  linear.set_input_hold(InputHold::Linear);
  Eigen::VectorXd y;
  ASSERT_TRUE(linear.simulate(x, d, y));
  StreamingModel stream(model, x, d.sample_time);
  ASSERT_TRUE(stream.valid());
  const double scale = std::max(1.0, y.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < n; ++k) ASSERT_NEAR(stream.step(d.u[k]), y[k], 1e-12 * scale) << "sample " << k;
}

}  // namespace
}  // namespace hystbench
