// The simulated MFC beam: gains normalised at the disturbance, the numbers of
// the modal model, and exact sampling against the closed-form response.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "framework/control/first_harmonic.hpp"
#include "framework/control/plant.hpp"

namespace hystbench {
namespace {

std::unique_ptr<Plant> beam(nlohmann::json params = nlohmann::json::object()) {
  const PlantInfo& info = PlantRegistry::instance().find("mfc_beam", "test");
  return info.create(validate_params(info.params, params, "test"), PlantSetup{});
}

double steady_rms(SignalStream& s, double amplitude, double hz, double fs, double seconds) {
  s.reset();
  const long n = std::lround(seconds * fs), steady = std::lround(10.0 * fs);
  double sum = 0.0;
  for (long k = 0; k < n; ++k) {
    const double y = s.step(amplitude * std::sin(2.0 * M_PI * hz * double(k) / fs));
    if (k >= n - steady) sum += y * y;
  }
  return std::sqrt(sum / double(steady));
}

TEST(MfcBeam, UncontrolledSteadyRmsIsOneOverRootTwo) {
  auto plant = beam();
  auto path = plant->disturbance_path();
  EXPECT_NEAR(steady_rms(*path, 3.0, 20.61, 1000.0, 60.0), std::sqrt(0.5), 0.01 * std::sqrt(0.5));
}

TEST(MfcBeam, GainsAreNormalisedAtTheDisturbance) {
  auto plant = beam();
  EXPECT_NEAR(std::abs(plant->control_response(20.61)), 1.0, 1e-12);
  EXPECT_NEAR(3.0 * std::abs(plant->disturbance_response(20.61)), 1.0, 1e-12);
  // Phases of the hand calculation of the modal model: P about -90.5 deg,
  // S about +90.4 deg (the two patches drive mode 2 with opposite signs).
  EXPECT_NEAR(std::arg(plant->disturbance_response(20.61)) * 180 / M_PI, -90.5, 0.1);
  EXPECT_NEAR(std::arg(plant->control_response(20.61)) * 180 / M_PI, 90.4, 0.1);
}

TEST(MfcBeam, ModalNumbersMatchTheHandCalculation) {
  const auto d = beam()->details();
  EXPECT_NEAR(d["length_m"].get<double>(), 0.4981, 1e-4);
  EXPECT_NEAR(d["control_gain"].get<double>(), 84.9510, 1e-3);
  EXPECT_NEAR(d["disturbance_gain"].get<double>(), 26.1376, 1e-3);
  const double f[] = {3.289, 20.610, 57.709}, ba[] = {1.0260, 3.7690, 4.3809},
               bd[] = {0.5751, -4.0831, -10.0996}, c[] = {1.7248, -1.0475, 0.4570};
  ASSERT_EQ(d["modes"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(d["modes"][i]["frequency_hz"].get<double>(), f[i], 1e-3) << i;
    EXPECT_NEAR(d["modes"][i]["control_input"].get<double>(), ba[i], 1e-4) << i;
    EXPECT_NEAR(d["modes"][i]["disturbance_input"].get<double>(), bd[i], 1e-4) << i;
    EXPECT_NEAR(d["modes"][i]["sensor"].get<double>(), c[i], 1e-4) << i;
  }
}

// A zero-order hold is, to first order, half a sample of delay and the
// gain sinc(wT/2): the exact discretisation matches the closed form times both.
TEST(MfcBeam, SampledPathsFollowTheClosedFormResponse) {
  auto plant = beam();
  for (double hz : {5.0, 20.61, 40.0}) {
    HarmonicProbe probe;
    probe.hz = hz;
    const double half = M_PI * hz / 1000.0;  // wT/2
    const std::complex<double> half_sample = std::polar(std::sin(half) / half, -half);
    const auto expected_s = plant->control_response(hz) * half_sample;
    const auto expected_p = plant->disturbance_response(hz) * half_sample;
    EXPECT_LT(std::abs(first_harmonic(*plant->control_path(), probe) - expected_s),
              5e-4 * std::abs(expected_s)) << hz;
    EXPECT_LT(std::abs(first_harmonic(*plant->disturbance_path(), probe) - expected_p),
              5e-4 * std::abs(expected_p)) << hz;
  }
}

TEST(MfcBeam, ExtraDelayShiftsTheControlPath) {
  auto plain = beam()->control_path();
  auto delayed = beam({{"extra_delay_samples", 3}})->control_path();
  std::vector<double> a, b;
  for (int k = 0; k < 50; ++k) {
    const double u = std::sin(0.3 * k);
    a.push_back(plain->step(u));
    b.push_back(delayed->step(u));
  }
  for (int k = 3; k < 50; ++k) EXPECT_EQ(b[k], a[k - 3]);
  EXPECT_EQ(b[0], 0.0);
}

TEST(MfcBeam, PatchOffTheBeamIsAnInputError) {
  try {
    beam({{"control_to_m", 0.9}});
    FAIL() << "expected an InputError";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("plant.params.control_from_m/control_to_m"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hystbench
