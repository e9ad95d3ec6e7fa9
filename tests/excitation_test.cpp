// Excitation segments and the sensor resolution of synthetic data: a
// multisine is the mean of its sines, hand-computed; the resolution rounds
// every output sample to its multiples.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/core/error.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/io/excitation.hpp"

namespace hystbench {
namespace {

TEST(Excitation, MultisineIsTheMeanOfItsSinesTimesTheAmplitude) {
  const Excitation ex = make_excitation(
      {{"sample_rate", 1000},
       {"segments", {{{"type", "multisine"}, {"frequencies", {10, 30}}, {"amplitude", 75}, {"offset", 75},
                      {"phase_deg", -90}, {"duration", 0.1}}}}});
  ASSERT_EQ(ex.u.size(), 100);
  EXPECT_EQ(ex.segment[0], "multisine_10/30Hz");
  EXPECT_NEAR(ex.u[0], 0.0, 1e-12);  // both cosines at their peak: 75 - 75
  // k = 7: 75 - 37.5 (cos(2π·0.07) + cos(2π·0.21))
  EXPECT_NEAR(ex.u[7], 75.0 - 37.5 * (std::cos(2 * M_PI * 0.07) + std::cos(2 * M_PI * 0.21)), 1e-12);
  EXPECT_LE(ex.u.maxCoeff(), 150.0);
  EXPECT_GE(ex.u.minCoeff(), 0.0);
}

TEST(Excitation, MultisineWithoutPositiveFrequenciesIsNamed) {
  for (const nlohmann::json& f : {nlohmann::json::array(), nlohmann::json{10, -1}, nlohmann::json("10")}) {
    try {
      make_excitation({{"sample_rate", 1000},
                       {"segments", {{{"type", "multisine"}, {"frequencies", f}, {"amplitude", 1}, {"duration", 1}}}}});
      FAIL() << f;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("excitation.segments[0].frequencies"), std::string::npos) << e.what();
    }
  }
}

TEST(SyntheticData, ResolutionRoundsEveryOutputSample) {
  const nlohmann::json excitation = {
      {"sample_rate", 1000},
      {"segments", {{{"type", "sine"}, {"frequency", 5}, {"amplitude", 10}, {"duration", 0.4}}}}};
  const Model model = Model::parse("msd");
  const nlohmann::json values = {{"gain", 0.37}, {"msd.period", 0.01}, {"msd.zeta", 0.3}};
  const auto fine = make_model_synthetic_data(model, values, excitation, 0.01, 4, "test");
  const auto coarse = make_model_synthetic_data(model, values, excitation, 0.01, 4, "test", 0.1);
  for (Eigen::Index k = 0; k < fine.data.y.size(); ++k) {
    EXPECT_DOUBLE_EQ(coarse.data.y[k], 0.1 * std::round(fine.data.y[k] / 0.1)) << k;
  }
  EXPECT_EQ(coarse.truth["noise"]["resolution"], 0.1);
}

}  // namespace
}  // namespace hystbench
