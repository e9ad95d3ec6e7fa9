// Saturation of shapes the catalog's formula does not hold exactly
// (problems/hammerstein/effects/saturation.cpp): the static part of the
// seed chain limited by tanh, by arctan and by a hard clip, planted here
// outside the catalog, then the seed chain without a limit fitted and
// diagnosed. Each must be named `saturation`, not `offset` or another
// effect that bends the loop, and the saturation candidate must reach the
// noise held out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "framework/discovery/diagnosis.hpp"
#include "framework/discovery/model_fit.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/model/holdout.hpp"

namespace hystbench {
namespace {

// The hidden-effect cases' short record (benchmarks/experiments/hidden_effects.json).
nlohmann::json test_excitation() {
  std::ifstream in(std::string(HYSTBENCH_SOURCE_DIR) + "/benchmarks/experiments/hidden_effects.json");
  return nlohmann::json::parse(in).at("test_excitation");
}

struct Shape {
  std::string name;
  std::function<double(double)> unit_limit;  // slope 1 at 0, limit ±1
  double limit = 0.0;                          // L in µm; 0: 0.8·max|w|
};

void PrintTo(const Shape& s, std::ostream* os) { *os << s.name; }

constexpr double kNoise = 0.012;  // of the noise-free output's RMS
constexpr std::uint64_t kSeed = 103;
const double kHiddenCaseLimit = 1.0 / std::sqrt(0.003);  // µm

// The seed chain's physics with its static part w limited to L·g(w/L):
// hysteresis and asymmetry simulated by the catalog, the
// limit applied here, then the mass-spring-damper (gain 1) on the limited
// signal. `sd` receives the noise's standard deviation and `effect_rms` the
// RMS change the limit makes to the noise-free output.
Measurement planted(const Shape& shape, double& sd, double& effect_rms, double& max_static) {
  const nlohmann::json static_values = {{"gain", 0.1},
                                        {"hysteresis.A", 0.02},
                                        {"hysteresis.beta", 0.005},
                                        {"hysteresis.gamma", 0.002},
                                        {"asymmetry.d2", 2e-4}};
  const SyntheticData part = make_model_synthetic_data(Model::parse("hysteresis,asymmetry"), static_values,
                                                       test_excitation(), 0.0, kSeed, "static part");
  const Eigen::VectorXd& w = part.data.y;
  max_static = w.cwiseAbs().maxCoeff();
  const double L = shape.limit > 0.0 ? shape.limit : 0.8 * w.cwiseAbs().maxCoeff();
  const auto dynamics = [&](const Eigen::VectorXd& drive) {
    Measurement m = part.data;
    m.u = drive;
    Eigen::VectorXd x(3), y;
    x << 1.0, 0.025, 0.1;  // gain, msd.period (s), msd.zeta
    EXPECT_TRUE(Model::parse("msd").simulate(x, ModelData(m, SignalScales{}), y));
    return y;
  };
  const Eigen::VectorXd limited = w.unaryExpr([&](double v) { return L * shape.unit_limit(v / L); });
  const Eigen::VectorXd clean = dynamics(limited);
  effect_rms = std::sqrt((clean - dynamics(w)).squaredNorm() / double(w.size()));
  sd = kNoise * std::sqrt(clean.squaredNorm() / double(clean.size()));
  std::mt19937_64 rng(kSeed);
  std::normal_distribution<double> normal(0.0, sd);
  Measurement m = part.data;
  m.y = clean.unaryExpr([&](double v) { return v + normal(rng); });
  return m;
}

class SaturationShape : public testing::TestWithParam<Shape> {};

TEST_P(SaturationShape, DiagnosedAsSaturationFromTheSeedChain) {
  double sd = 0.0, effect_rms = 0.0, max_static = 0.0;
  const Measurement m = planted(GetParam(), sd, effect_rms, max_static);
  EXPECT_GT(effect_rms, 2.0 * sd) << "the limit barely shows in these data";
  ModelData data(m, SignalScales::of(m));
  apply_holdout(data, HoldoutSpec{});
  DiagnoseOptions options;
  options.fit.seed = kSeed;
  const Model start = Model::parse("hysteresis,asymmetry,msd");
  const Diagnosis d = diagnose(start, fit_model(start, data, options.fit).x, data, options);
  const Candidate* saturation = d.find("saturation");
  ASSERT_NE(saturation, nullptr);
  const auto names = saturation->model.parameter_names();
  const double softness = saturation->x[std::find(names.begin(), names.end(), "saturation.softness") - names.begin()];
  std::printf("[ %-7s ] max|w| %.2f µm; effect RMS %.2f sd; verdict %s; seed chain %.3f sd held out, with saturation %.3f sd "
              "(softness %.3f)\n",
              GetParam().name.c_str(), max_static, effect_rms / sd, d.verdict.c_str(), d.errors.rmse_heldout / sd,
              saturation->after.rmse_heldout / sd, softness);
  EXPECT_EQ(d.verdict, "saturation");
  EXPECT_LE(saturation->after.rmse_heldout, 1.2 * sd);
}

INSTANTIATE_TEST_SUITE_P(
    Planted, SaturationShape,
    // tanh and arctan at the hidden-effect case's limit (lambda = 0.003/µm²),
    // the soft limit of an actuator; the clip where it cuts the top fifth.
    testing::Values(Shape{"tanh", [](double x) { return std::tanh(x); }, kHiddenCaseLimit},
                    Shape{"arctan", [](double x) { return 2.0 / std::numbers::pi * std::atan(std::numbers::pi / 2.0 * x); },
                          kHiddenCaseLimit},
                    Shape{"clip", [](double x) { return std::clamp(x, -1.0, 1.0); }}),
    [](const testing::TestParamInfo<Shape>& info) { return info.param.name; });

}  // namespace
}  // namespace hystbench
