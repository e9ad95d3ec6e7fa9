// Models run sample by sample (StreamingModel, docs/models.md#streaming-models):
// the stream gives what the batch simulation gives under the same causal
// input hold, for every catalog effect and for chains of them; no output
// moves when later inputs change; the spline hold is refused; divergence,
// invalid parameters, reset and clone behave.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/model/model.hpp"
#include "framework/model/replay_stepper.hpp"
#include "framework/model/streaming_model.hpp"
#include "tests/active_point.hpp"

namespace hystbench {
namespace {

constexpr InputHold kCausalHolds[] = {InputHold::Linear, InputHold::Zoh};

// 2 s at 1 kHz in normalised units: a multisine from 3 to 150 Hz with a step
// at 1 s, so that loops reverse, resonances ring and lags see a level change.
ModelData record(Eigen::Index n = 2000, double ts = 1e-3) {
  ModelData d;
  d.sample_time = ts;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, ts * double(n - 1));
  d.u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 8; ++i) {
    const double f = 3.0 + 21.0 * i, phase = 0.9 * i * i;
    for (Eigen::Index k = 0; k < n; ++k)
      d.u[k] += 0.45 * std::sin(2.0 * std::numbers::pi * f * d.t[k] + phase);
  }
  d.u.tail(n / 2).array() += 0.6;
  d.y = Eigen::VectorXd::Zero(n);
  d.estimation = Eigen::VectorXd::Ones(n);
  return d;
}

std::vector<std::string> catalog() {
  std::vector<std::string> names;
  for (const auto* info : EffectRegistry::instance().all()) names.push_back(info->name);
  return names;
}

using test_support::active_point;

bool batch(Model model, const Eigen::VectorXd& x, const ModelData& d, InputHold hold, Eigen::VectorXd& y) {
  model.set_input_hold(hold);
  return model.simulate(x, d, y);
}

Eigen::VectorXd stream(const Model& model, const Eigen::VectorXd& x, const ModelData& d, InputHold hold) {
  StreamingModel s(model, x, d.sample_time, hold);
  EXPECT_TRUE(s.valid());
  Eigen::VectorXd y(d.size());
  for (Eigen::Index k = 0; k < d.size(); ++k) y[k] = s.step(d.u[k]);
  return y;
}

// The largest active point (of a few) at which the batch simulation is valid.
Eigen::VectorXd valid_active_point(const Model& model, const ModelData& d, InputHold hold) {
  Eigen::VectorXd y;
  for (double step : {0.25, 0.1, 0.03}) {
    const Eigen::VectorXd x = active_point(model, step);
    if (batch(model, x, d, hold, y)) return x;
  }
  ADD_FAILURE() << "no valid point near neutral for " << model.text();
  return model.neutral();
}

// max |stream − batch| <= 1e-12 · max(1, max |batch|).
void expect_stream_equals_batch(const std::string& effects, InputHold hold) {
  SCOPED_TRACE(effects + " under " + to_string(hold));
  const Model model = Model::parse(effects);
  const ModelData d = record();
  const Eigen::VectorXd x = valid_active_point(model, d, hold);
  Eigen::VectorXd y_batch;
  ASSERT_TRUE(batch(model, x, d, hold, y_batch));
  const Eigen::VectorXd y_stream = stream(model, x, d, hold);
  ASSERT_TRUE(y_stream.allFinite());
  const double scale = std::max(1.0, y_batch.cwiseAbs().maxCoeff());
  EXPECT_LE((y_stream - y_batch).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_GT((y_batch - 1.3 * d.u).cwiseAbs().maxCoeff(), 1e-6) << "the chain does nothing";
}

TEST(StreamingModel, EqualsBatchForEveryCatalogEffect) {
  for (const auto& name : catalog())
    for (InputHold hold : kCausalHolds) expect_stream_equals_batch(name, hold);
}

TEST(StreamingModel, EqualsBatchForTheSeedChainAndForEveryEffectTogether) {
  for (InputHold hold : kCausalHolds) {
    expect_stream_equals_batch("hysteresis,asymmetry,msd,arx", hold);
    expect_stream_equals_batch(join(catalog(), ","), hold);
  }
}

TEST(StreamingModel, CatalogEffectsStepWithoutReplayingTheHistory) {
  // The replay stepper costs O(k) at sample k: fine for a user's effect,
  // too slow for the catalog's.
  for (const auto& name : catalog()) {
    SCOPED_TRACE(name);
    const Model model = Model::parse(name);
    const Eigen::VectorXd x = active_point(model, 0.1);
    const auto& e = model.chain().front();
    const auto stepper = e.effect->stepper({x.data() + e.offset, e.info->params.size()},
                                           StepContext{1e-3, InputHold::Linear, 0});
    ASSERT_TRUE(stepper);
    EXPECT_EQ(dynamic_cast<const ReplayStepper*>(stepper.get()), nullptr);
  }
}

TEST(StreamingModel, PastOutputsIgnoreFutureInputs) {
  // Changing the input from sample k0 on leaves every output before k0
  // exactly alone, in the stream and in the batch simulation under the same
  // causal hold; later outputs do change.
  const ModelData d = record();
  ModelData later = d;
  const Eigen::Index k0 = 900;
  later.u.tail(d.size() - k0).array() += 0.5;
  for (const auto& name : catalog()) {
    const Model model = Model::parse(name);
    for (InputHold hold : kCausalHolds) {
      SCOPED_TRACE(name + " under " + to_string(hold));
      const Eigen::VectorXd x = valid_active_point(model, d, hold);
      Eigen::VectorXd y, y_later;
      ASSERT_TRUE(batch(model, x, d, hold, y));
      ASSERT_TRUE(batch(model, x, later, hold, y_later));
      EXPECT_EQ(y.head(k0), y_later.head(k0)) << "batch";
      EXPECT_NE(y.tail(d.size() - k0), y_later.tail(d.size() - k0)) << "batch";
      const Eigen::VectorXd s = stream(model, x, d, hold), s_later = stream(model, x, later, hold);
      EXPECT_EQ(s.head(k0), s_later.head(k0)) << "stream";
      EXPECT_NE(s.tail(d.size() - k0), s_later.tail(d.size() - k0)) << "stream";
    }
  }
}

TEST(StreamingModel, SplineHoldSeesTheFutureSoTheStreamRefusesIt) {
  const Model model = Model::parse("feedback_hysteresis");
  const ModelData d = record();
  ModelData later = d;
  const Eigen::Index k0 = 900;
  later.u.tail(d.size() - k0).array() += 0.5;
  const Eigen::VectorXd x = valid_active_point(model, d, InputHold::Spline);
  Eigen::VectorXd y, y_later;
  ASSERT_TRUE(batch(model, x, d, InputHold::Spline, y));
  ASSERT_TRUE(batch(model, x, later, InputHold::Spline, y_later));
  EXPECT_NE(y.head(k0), y_later.head(k0)) << "the spline through the record reaches back";
  try {
    StreamingModel s(model, x, d.sample_time, InputHold::Spline, "plant");
    ADD_FAILURE() << "a stream with the spline hold was built";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "plant: a stream needs a causal input hold (linear or zoh), not spline, which fits "
              "the whole record");
  }
}

TEST(StreamingModel, ResetRestartsAndCloneContinuesFromTheSameState) {
  const Model model = Model::parse("backlash,delay,hysteresis,msd,feedback_hysteresis,creep,drift");
  const ModelData d = record(600);
  const Eigen::VectorXd x = valid_active_point(model, d, InputHold::Linear);
  StreamingModel s(model, x, d.sample_time);
  Eigen::VectorXd first(d.size());
  for (Eigen::Index k = 0; k < d.size(); ++k) first[k] = s.step(d.u[k]);
  s.reset();
  for (Eigen::Index k = 0; k < 300; ++k) ASSERT_EQ(s.step(d.u[k]), first[k]) << "sample " << k;
  const auto copy = s.clone();
  for (Eigen::Index k = 300; k < d.size(); ++k) {
    ASSERT_EQ(copy->step(d.u[k]), first[k]) << "clone, sample " << k;
    ASSERT_EQ(s.step(d.u[k]), first[k]) << "original, sample " << k;
  }
}

TEST(StreamingModel, InvalidParametersAndDivergenceGiveNaN) {
  const ModelData d = record(400);
  const Model arx = Model::parse("arx");
  Eigen::VectorXd x = arx.neutral();
  x[1] = 1.9;  // a1 outside the Jury triangle
  StreamingModel invalid(arx, x, d.sample_time);
  EXPECT_FALSE(invalid.valid());
  EXPECT_TRUE(std::isnan(invalid.step(1.0)));

  // A violent alternating drive makes the Bouc-Wen loop explode; saturation's
  // limit would hide it, so the loop itself has to report it.
  std::vector<double> alternating(400);
  for (std::size_t k = 0; k < alternating.size(); ++k) alternating[k] = k % 2 ? 3.0 : -3.0;
  for (const char* effects : {"hysteresis", "hysteresis,saturation"}) {
    SCOPED_TRACE(effects);
    const Model model = Model::parse(effects);
    Eigen::VectorXd p = model.neutral();
    p.segment(1, 3) << 10.0, 10.0, -10.0;
    if (model.dimension() > 4) p[4] = 1.0;
    StreamingModel s(model, p, d.sample_time);
    ASSERT_TRUE(s.valid());
    std::size_t first_nan = alternating.size();
    for (std::size_t k = 0; k < alternating.size(); ++k) {
      const double y = s.step(alternating[k]);
      if (std::isnan(y) && first_nan == alternating.size()) first_nan = k;
      if (first_nan < k) {
        ASSERT_TRUE(std::isnan(y)) << "NaN stays until reset, sample " << k;
      }
    }
    EXPECT_LT(first_nan, alternating.size());
    s.reset();
    EXPECT_FALSE(std::isnan(s.step(0.1))) << "reset starts again";
  }
}

TEST(InputHold, NamesRoundTripAndAnUnknownNameListsTheValidOnes) {
  for (InputHold hold : {InputHold::Spline, InputHold::Linear, InputHold::Zoh})
    EXPECT_EQ(parse_input_hold(to_string(hold), "--input-hold"), hold);
  EXPECT_FALSE(is_causal(InputHold::Spline));
  EXPECT_TRUE(is_causal(InputHold::Linear));
  EXPECT_TRUE(is_causal(InputHold::Zoh));
  try {
    parse_input_hold("cubic", "--input-hold");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--input-hold: unknown input hold 'cubic'; valid: spline, linear, zoh, bandlimited");
  }
  EXPECT_EQ(Model::parse("msd").input_hold(), InputHold::Spline) << "the offline default";
  Model m = Model::parse("msd");
  m.set_input_hold(InputHold::Zoh);
  EXPECT_EQ(m.with("creep").input_hold(), InputHold::Zoh);
  EXPECT_EQ(m.without("msd").input_hold(), InputHold::Zoh);
}

// Error of each hold against the same oscillator driven by a 10× finer
// record of the same multisine (up to 0.15 of the sample rate): the
// band-limited hold is the most accurate, then the spline (the offline
// default), zero-order hold the least.
TEST(InputHold, BandLimitedIsMostAccurateOfflineAndZeroOrderHoldLeast) {
  const double ts = 1e-3;
  const int fine = 10;
  const Eigen::Index n = 3000;
  auto multisine = [](Eigen::Index count, double step) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(count);
    for (int i = 0; i < 12; ++i)
      for (Eigen::Index k = 0; k < count; ++k)
        u[k] += 0.41 * std::sin(2.0 * std::numbers::pi * (5.0 + 12.5 * i) * step * double(k) + 0.7 * i * i);
    return u;
  };
  auto data = [](const Eigen::VectorXd& u, double step) {
    ModelData d;
    d.sample_time = step;
    d.t = Eigen::VectorXd::LinSpaced(u.size(), 0.0, step * double(u.size() - 1));
    d.u = u;
    return d;
  };
  const Model model = Model::parse("feedback_hysteresis");
  Eigen::VectorXd x(6);
  x << 1.5, 1.0 / 25.0, 0.05, 1.0, 0.53, -0.73;  // benchmark-like: 25 Hz, strong hysteresis
  Eigen::VectorXd reference;
  ASSERT_TRUE(batch(model, x, data(multisine(n * fine, ts / fine), ts / fine), InputHold::Spline, reference));
  std::vector<double> error;
  for (InputHold hold : {InputHold::Spline, InputHold::Linear, InputHold::Zoh, InputHold::Bandlimited}) {
    Eigen::VectorXd y;
    ASSERT_TRUE(batch(model, x, data(multisine(n, ts), ts), hold, y));
    double sse = 0.0, power = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      sse += std::pow(y[k] - reference[k * fine], 2);
      power += std::pow(reference[k * fine], 2);
    }
    error.push_back(std::sqrt(sse / power));
    std::cout << "[ hold     ] " << to_string(hold) << ": relative RMS error " << error.back() << "\n";
  }
  EXPECT_LT(error[3], error[0]);
  EXPECT_LT(error[0], error[1]);
  EXPECT_LT(error[1], error[2]);
}

}  // namespace
}  // namespace hystbench
