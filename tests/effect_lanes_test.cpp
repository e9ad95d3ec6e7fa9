// Batched effect chain: a model whose effects all have a batched form
// evaluates candidates in blocks, and every value equals the one-candidate
// path bit for bit - neutral, invalid and diverging candidates included.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "framework/core/rng.hpp"
#include "framework/model/model.hpp"
#include "framework/model/model_problem.hpp"
#include "tests/lane_record.hpp"

namespace hystbench {
namespace {

void expect_bit_identical(const std::string& effects, int samples = 3000, InputHold hold = InputHold::Spline,
                          int substeps = 0) {
  Model model = Model::parse(effects);
  model.set_input_hold(hold);
  model.set_substeps(substeps);
  const ModelData data = lane_record(samples);
  const ModelProblem problem(model, data);
  ASSERT_TRUE(problem.batched()) << effects;
  // 19 candidates: two full blocks and a partial one (at 8 lanes).
  const Eigen::MatrixXd X = lane_candidates(model, 19, 7);
  Eigen::VectorXd f(X.cols());
  problem.evaluate(X, f);
  int finite = 0, infinite = 0;
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    EXPECT_EQ(f[j], problem.sse(X.col(j))) << effects << ", candidate " << j;
    (std::isfinite(f[j]) ? finite : infinite)++;
  }
  EXPECT_GT(finite, 0) << effects;
}

TEST(EffectLanes, BlocksGiveExactlyTheOneCandidateValues) {
  for (const char* effects : {"hysteresis", "asymmetry", "msd", "arx", "creep", "offset", "drift", "backlash",
                              "saturation", "second_mode", "delay", "hysteresis,asymmetry,msd,arx",
                              "hysteresis,asymmetry,msd,arx,creep,offset,drift",
                              "backlash,hysteresis,asymmetry,saturation,msd,second_mode",
                              "delay,hysteresis,asymmetry,msd"})
    expect_bit_identical(effects);
}

// Blocks run a chunk of samples at a time, each effect carrying its state
// into the next chunk, and sum each lane's SSE in Eigen's order as the
// chunks pass: records shorter than one packet of Eigen's sum, than two,
// than a chunk, a whole number of chunks and a partial last chunk (with a
// packet and single samples left over) give the same values.
TEST(EffectLanes, ChunkBoundariesDoNotChangeAValue) {
  for (int samples : {1, 3, 5, 12, 23, 700, 2048, 2049, 5000})
    expect_bit_identical("hysteresis,asymmetry,msd,arx,creep,offset,drift", samples);
}

// The Bouc-Wen and Duffing oscillators run a block over the whole record:
// lanes with one sub-step count together (a kinked sub-step redone per lane), lanes whose
// stiffness asks for more sub-steps each alone; under every input hold.
TEST(EffectLanes, TheFeedbackOscillatorGivesExactlyTheOneCandidateValues) {
  for (const char* effects : {"feedback_hysteresis", "hysteresis,asymmetry,feedback_hysteresis,arx", "duffing",
                              "asymmetry,duffing,offset"})
    for (InputHold hold : {InputHold::Spline, InputHold::Linear, InputHold::Zoh, InputHold::Bandlimited})
      expect_bit_identical(effects, 600, hold);
  expect_bit_identical("feedback_hysteresis", 600, InputHold::Spline, 3);
  expect_bit_identical("feedback_hysteresis", 600, InputHold::Bandlimited, 3);
  for (int samples : {1, 2, 3, 4}) {
    expect_bit_identical("feedback_hysteresis", samples);
    expect_bit_identical("feedback_hysteresis", samples, InputHold::Bandlimited);
  }
}

// Fixed blocks for the oscillator's other paths: lanes in groups of one
// sub-step count each (four lanes, two lanes, and a lane stiff enough to need
// more sub-steps, which runs alone), an invalid lane, and a block whose every
// lane diverges (the block stops early); under both holds through the whole record.
void expect_stiff_invalid_and_diverging_lanes(InputHold hold) {
  Model model = Model::parse("feedback_hysteresis");
  model.set_input_hold(hold);
  const ModelData data = lane_record(600);
  const ModelProblem problem(model, data);
  const auto names = model.parameter_names();
  const auto index = [&](const std::string& name) {
    return int(std::find(names.begin(), names.end(), "feedback_hysteresis." + name) - names.begin());
  };
  Eigen::MatrixXd X = model.neutral().replicate(1, 16);
  for (Eigen::Index j = 0; j < 16; ++j) {
    X(index("period"), j) = j == 5 || j == 6 ? 0.03 : 0.02;
    X(index("alpha"), j) = 0.5;
    X(index("beta_gamma"), j) = 0.3;
  }
  // Stiffness 2π·Ts/period·√(1 + α)·(ζ + √(ζ² + 1)) ≈ 24 > 20 sub-steps.
  X(index("period"), 1) = 0.005, X(index("zeta"), 1) = 2.0, X(index("alpha"), 1) = 4.0;
  X(index("period"), 2) = -0.1;  // invalid
  // The second block diverges in every lane: with β·γ < 0 < β·δ a positive
  // z grows on every stroke, by up to e^(6|Δy|) when y falls.
  for (Eigen::Index j = 8; j < 16; ++j) {
    X(0, j) = 20.0;
    X(index("beta_gamma"), j) = -3.0;
    X(index("beta_delta"), j) = 3.0;
  }
  Eigen::VectorXd f(16);
  problem.evaluate(X, f);
  for (Eigen::Index j = 0; j < 16; ++j)
    EXPECT_EQ(f[j], problem.sse(X.col(j))) << to_string(hold) << ", candidate " << j;
  EXPECT_TRUE(std::isfinite(f[1]));
  EXPECT_EQ(f[2], std::numeric_limits<double>::infinity());
  for (Eigen::Index j = 8; j < 16; ++j) EXPECT_EQ(f[j], std::numeric_limits<double>::infinity()) << j;
}

TEST(EffectLanes, TheFeedbackOscillatorsStiffInvalidAndDivergingLanes) {
  for (InputHold hold : {InputHold::Spline, InputHold::Bandlimited}) expect_stiff_invalid_and_diverging_lanes(hold);
}

// An output finite but too large to square (here a gain of 1e160) is a
// diverged candidate: its SSE is infinite both ways, not NaN (inf times the
// held-out samples' weight 0), which no optimizer can rank.
TEST(EffectLanes, AnOutputTooLargeToSquareIsInfiniteNotNan) {
  const Model model = Model::parse("msd");
  const ModelData data = lane_record(600);
  const ModelProblem problem(model, data);
  Eigen::MatrixXd X = model.neutral().replicate(1, 3);
  X(0, 1) = 1e160;
  Eigen::VectorXd f(3);
  problem.evaluate(X, f);
  EXPECT_TRUE(std::isfinite(f[0]));
  EXPECT_EQ(f[1], std::numeric_limits<double>::infinity());
  EXPECT_EQ(problem.sse(X.col(1)), std::numeric_limits<double>::infinity());
}

TEST(EffectLanes, DivergingAndInvalidCandidatesAreInfiniteInTheirLaneOnly) {
  const Model model = Model::parse("hysteresis,asymmetry,msd,arx");
  const ModelData data = lane_record();
  const ModelProblem problem(model, data);
  Eigen::MatrixXd X = model.neutral().replicate(1, 8);
  const auto names = model.parameter_names();
  const auto index = [&](const std::string& name) {
    return int(std::find(names.begin(), names.end(), name) - names.begin());
  };
  X(index("arx.a1"), 2) = 1.9;       // outside the Jury triangle: invalid
  X(index("hysteresis.A"), 5) = 10;  // a violent loop
  X(index("hysteresis.beta"), 5) = -1e3;
  Eigen::VectorXd f(8);
  problem.evaluate(X, f);
  EXPECT_EQ(f[2], std::numeric_limits<double>::infinity());
  EXPECT_EQ(f[5], problem.sse(X.col(5)));
  for (int j : {0, 1, 3, 4, 6, 7}) EXPECT_EQ(f[j], problem.sse(X.col(j)));
  EXPECT_TRUE(std::isfinite(f[0]));
}

}  // namespace
}  // namespace hystbench
