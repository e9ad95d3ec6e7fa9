// A fit refuses data too short for its model: 10 estimation samples per
// parameter, never fewer than 20 (framework/discovery/data_source).
#include <gtest/gtest.h>

#include <string>

#include "framework/core/error.hpp"
#include "framework/discovery/data_source.hpp"

namespace hystbench {
namespace {

// `n` samples of a ramp at 1 kHz, read from "short.csv".
Measurement ramp(Eigen::Index n) {
  Measurement m;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * double(n - 1));
  m.u = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
  m.y = m.u;
  m.sample_time = 1e-3;
  m.source = "short.csv";
  return m;
}

std::string fit_data_error(Eigen::Index n, const std::string& holdout, const std::string& model) {
  const Measurement m = ramp(n);
  try {
    prepare_fit_data(m, SignalScales::of(m), HoldoutSpec::parse(holdout), Model::parse(model));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << n << " samples were accepted for " << model;
  return {};
}

TEST(FitData, NeedsTenSamplesPerParameterAndTwentyAtTheLeast) {
  // gain + hysteresis (A, beta, gamma) + asymmetry (d2) + msd (period, zeta)
  EXPECT_EQ(samples_needed(Model::parse("hysteresis,asymmetry,msd")), 70);
  EXPECT_EQ(samples_needed(Model::parse("msd")), 30);
  EXPECT_EQ(samples_needed(Model::parse("none")), 20);  // one parameter, but 20 at the least
  EXPECT_EQ(samples_needed(Model::parse("offset")), 20);
}

TEST(FitData, RefusesFewerNamingFileModelAndRule) {
  EXPECT_EQ(fit_data_error(3, "none", "hysteresis,asymmetry,msd"),
            "short.csv: 3 samples to fit, but the model hysteresis,asymmetry,msd has 7 parameters "
            "and needs at least 70 (10 per parameter, 20 at the least); give more data or a "
            "smaller model");
  EXPECT_EQ(fit_data_error(19, "none", "none"),
            "short.csv: 19 samples to fit, but the model none has 1 parameter and needs at least "
            "20 (10 per parameter, 20 at the least); give more data or a smaller model");
  const Measurement m = ramp(70);
  const ModelData d = prepare_fit_data(m, SignalScales::of(m), HoldoutSpec::parse("none"),
                                       Model::parse("hysteresis,asymmetry,msd"));
  EXPECT_EQ(d.estimation_count(), 70);
}

// Held-out samples are never fitted, so they do not count.
TEST(FitData, CountsOnlyTheEstimationSamples) {
  // last:0.25 of 80 holds out floor(20) samples, leaving 60 for 70 needed.
  EXPECT_EQ(fit_data_error(80, "last:0.25", "hysteresis,asymmetry,msd"),
            "short.csv: 60 samples to fit (80 in the file, 20 held out), but the model "
            "hysteresis,asymmetry,msd has 7 parameters and needs at least 70 (10 per parameter, "
            "20 at the least); give more data, hold out fewer samples (--holdout) or a smaller "
            "model");
  const Measurement m = ramp(80);
  EXPECT_NO_THROW(prepare_fit_data(m, SignalScales::of(m), HoldoutSpec::parse("none"),
                                   Model::parse("hysteresis,asymmetry,msd")));
}

}  // namespace
}  // namespace hystbench
