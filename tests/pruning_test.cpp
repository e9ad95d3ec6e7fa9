// Pruning under the nesting rule (framework/discovery/pruning.hpp): a model
// handed to pruning off its optimum is refitted from the better sub-model
// before any removal is judged, so no effect the data have is removed
// because a poor local fit of it made the model look worse than without it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/discovery/diagnosis.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/pruning.hpp"

namespace hystbench {
namespace {

// y = 2u + 0.3 + 0.2·t + noise (σ 0.02), u a 3 Hz sine at 1 kHz over 2 s:
// the data have a gain, an offset and a drift.
ModelData gain_offset_drift_data() {
  const int n = 2000;
  Measurement m;
  m.sample_time = 1e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * (n - 1));
  m.u = (2 * M_PI * 3.0 * m.t.array()).sin().matrix();
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 0.02);
  m.y.resize(n);
  for (int k = 0; k < n; ++k) m.y[k] = 2.0 * m.u[k] + 0.3 + 0.2 * m.t[k] + normal(rng);
  return ModelData(m, {});
}

FitOptions small_fit() {
  FitOptions f;
  f.restarts = 1;
  f.evaluations = 2000;
  f.local_evaluations = 500;
  return f;
}

FitResult at(const Model& model, const Eigen::VectorXd& x, const ModelData& d) {
  return FitResult{model, x, fit_errors(model, x, d).sse, 0, 0.0, {}};
}

TEST(Pruning, AModelOffItsOptimumIsRefittedFromItsBetterSubModelAndKeepsItsEffects) {
  const ModelData d = gain_offset_drift_data();
  const Model model = Model::parse("offset,drift");
  // The right gain and offset, the drift far off with the wrong sign: every
  // model with one effect less, polished from here, fits better.
  Eigen::VectorXd x(3);
  x << 2.0, 0.3, -0.9;
  const FitResult bad = at(model, x, d);
  const Pruned p = prune(bad, "", d, small_fit());
  EXPECT_TRUE(p.removed.empty()) << "removed " << p.removed.front();
  ASSERT_FALSE(p.refits.empty()) << "the nesting rule did not fire";
  EXPECT_EQ(p.refits.front().model, model.text());
  EXPECT_LE(p.refits.front().sse_after, p.refits.front().sse_from);
  EXPECT_TRUE(p.fit.model.has("offset") && p.fit.model.has("drift"));
  EXPECT_NEAR(p.fit.x[2], 0.2, 0.01);
  // The invariant: the pruned fit is at least as good as every sub-model
  // tried in its last round.
  ASSERT_EQ(p.tried.size(), 2u);  // without the offset, without the drift
  for (const auto& s : p.tried) EXPECT_LE(p.fit.sse, s.sse * (1 + kNestingTolerance)) << s.model;
}

TEST(Pruning, AModelAtItsOptimumIsLeftAloneAndARedundantEffectStillGoes) {
  const ModelData d = gain_offset_drift_data();
  // Started at the truth, no sub-model comes near: nothing to refit or
  // remove. With a creep the data do not have, the creep goes.
  const Model model = Model::parse("offset,drift");
  Eigen::VectorXd x(3);
  x << 2.0, 0.3, 0.2;
  const Pruned kept = prune(at(model, x, d), "", d, small_fit());
  EXPECT_TRUE(kept.removed.empty());
  EXPECT_TRUE(kept.refits.empty());

  const Model larger = Model::parse("offset,drift,creep");
  const Pruned pruned = prune(at(larger, larger.carry_over(model, x), d), "", d, small_fit());
  EXPECT_EQ(pruned.removed, std::vector<std::string>{"creep"});
}

TEST(Pruning, AProtectedEffectStaysAndSaysBicWantedItGone) {
  // The data have no drift; BIC would remove it, but it is protected.
  ModelData d = gain_offset_drift_data();
  d.y -= 0.2 * d.t;
  const Model model = Model::parse("offset,drift");
  Eigen::VectorXd x(3);
  x << 2.0, 0.3, 0.0;
  const KeepReason keep_drift = [](const std::string& effect, const FitResult&,
                                   const FitResult&) -> std::optional<std::string> {
    if (effect == "drift") return "the test says so";
    return std::nullopt;
  };
  const Pruned p = prune(at(model, x, d), "", d, small_fit(), keep_drift);
  EXPECT_TRUE(p.removed.empty());
  ASSERT_EQ(p.held.size(), 1u);
  EXPECT_EQ(p.held[0].effect, "drift");
  EXPECT_EQ(p.held[0].reason, "the test says so");
  const Pruned unprotected = prune(at(model, x, d), "", d, small_fit());
  EXPECT_EQ(unprotected.removed, std::vector<std::string>{"drift"});
}

TEST(Pruning, NestingRefitsRoundTripThroughJson) {
  const std::vector<NestingRefit> refits{{"offset,drift", "offset", 2.0, 1.0, 0.5}};
  const auto back = nesting_refits_from_json(to_json(refits));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].from, "offset");
  EXPECT_EQ(back[0].sse_after, 0.5);
  EXPECT_NE(refits[0].sentence().find("offset fitted better than offset,drift"), std::string::npos);
}

}  // namespace
}  // namespace hystbench
