// What a record excites (framework/discovery/excitation_content.hpp) and which
// effect pairs it can tell apart (separability.hpp), on inputs whose
// answer is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "framework/discovery/excitation_content.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/discovery/startup_transient.hpp"

namespace hystbench {
namespace {

constexpr double kTs = 1e-3;

// `seconds` of a sine of `hz` and `amplitude`, appended to u.
void sine(std::vector<double>& u, double hz, double amplitude, double seconds) {
  const auto n = std::size_t(std::lround(seconds / kTs));
  for (std::size_t k = 0; k < n; ++k) u.push_back(amplitude * std::sin(2 * M_PI * hz * double(k) * kTs));
}

void hold(std::vector<double>& u, double level, double seconds) {
  u.insert(u.end(), std::size_t(std::lround(seconds / kTs)), level);
}

ExcitationContent of(const std::vector<double>& u) {
  return describe_excitation(Eigen::Map<const Eigen::VectorXd>(u.data(), Eigen::Index(u.size())), {}, kTs, "V");
}

TEST(ExcitationContent, OneSineAfterARestIsOneFrequencyAtOneAmplitude) {
  std::vector<double> u;
  hold(u, 0.0, 3.0);
  sine(u, 1.0, 75.0, 10.0);
  const ExcitationContent e = of(u);
  ASSERT_EQ(e.parts.size(), 1u);
  EXPECT_TRUE(e.parts[0].tone);
  EXPECT_NEAR(e.parts[0].frequency_hz, 1.0, 0.02);
  EXPECT_NEAR(e.parts[0].periods, 10.0, 0.2);
  EXPECT_NEAR(e.amplitude_high, 75.0, 1.0);
  ASSERT_EQ(e.rests.size(), 1u);
  EXPECT_NEAR(e.rest_seconds(), 3.0, 0.01);
  EXPECT_FALSE(e.rests[0].after_change);  // a rest at the start is no step
  EXPECT_FALSE(e.meets(ExcitationNeed::SeveralFrequencies));
  EXPECT_FALSE(e.meets(ExcitationNeed::SeveralAmplitudes));
  EXPECT_FALSE(e.meets(ExcitationNeed::HeldLevel));
  const std::string s = e.summary();
  EXPECT_NE(s.find("one frequency (1 Hz)"), std::string::npos) << s;
  EXPECT_NE(s.find("one amplitude (75 V)"), std::string::npos) << s;
  EXPECT_NE(s.find("3 s at rest"), std::string::npos) << s;  // 3.006 s, to two digits
}

TEST(ExcitationContent, SinesOverADecadeAtTwoAmplitudesAndAHeldStep) {
  std::vector<double> u;
  sine(u, 2.0, 40.0, 2.0);
  sine(u, 20.0, 80.0, 0.5);
  hold(u, 30.0, 1.0);  // a step to 30, held for 1 s
  const ExcitationContent e = of(u);
  EXPECT_TRUE(e.meets(ExcitationNeed::SeveralFrequencies)) << e.to_json().dump();
  EXPECT_TRUE(e.meets(ExcitationNeed::SeveralAmplitudes)) << e.to_json().dump();
  EXPECT_TRUE(e.meets(ExcitationNeed::HeldLevel));
}

TEST(ExcitationContent, ABroadbandInputSpansItsBand) {
  // Equal-amplitude tones every 5 Hz from 5 to 100 Hz: no single line
  // holds the power.
  std::vector<double> u(20000, 0.0);
  for (int f = 5; f <= 100; f += 5)
    for (std::size_t k = 0; k < u.size(); ++k) u[k] += std::sin(2 * M_PI * f * double(k) * kTs + f);
  const ExcitationContent e = of(u);
  ASSERT_EQ(e.parts.size(), 1u);
  EXPECT_FALSE(e.parts[0].tone);
  EXPECT_LT(e.low_hz, 12.0);
  EXPECT_GT(e.high_hz, 90.0);
  EXPECT_TRUE(e.meets(ExcitationNeed::SeveralFrequencies));
}

TEST(Separability, HysteresisAndALagAtOneFrequencyAreNamedWithTheAdvice) {
  std::vector<double> u;
  sine(u, 1.0, 75.0, 10.0);
  const ExcitationContent e = of(u);
  const auto pairs = inseparable_pairs({"hysteresis", "asymmetry", "msd"}, e);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].effect, "hysteresis");
  EXPECT_EQ(pairs[0].rival, "msd");
  const std::string s = pairs[0].sentence(e);
  EXPECT_NE(s.find("cannot tell hysteresis from msd"), std::string::npos) << s;
  EXPECT_NE(s.find("three frequencies over a decade"), std::string::npos) << s;
  // Declared on either side: msd finds hysteresis too; and an effect that
  // generalises msd inherits its rivals.
  EXPECT_EQ(inseparable_from("msd", {"hysteresis"}, e).size(), 1u);
  EXPECT_EQ(inseparable_from("hysteresis", {"feedback_hysteresis"}, e).size(), 1u);

  std::vector<double> wide;
  sine(wide, 1.0, 75.0, 5.0);
  sine(wide, 10.0, 75.0, 1.0);
  EXPECT_TRUE(inseparable_pairs({"hysteresis", "asymmetry", "msd"}, of(wide)).empty());
}

TEST(Separability, SaturationAndAsymmetryNeedTwoAmplitudesCreepAHeldLevel) {
  std::vector<double> u;
  sine(u, 1.0, 75.0, 4.0);
  sine(u, 10.0, 75.0, 1.0);
  const ExcitationContent e = of(u);
  const auto pairs = inseparable_pairs({"asymmetry", "saturation", "creep", "drift", "offset"}, e);
  std::vector<std::string> names;
  for (const auto& p : pairs) names.push_back(p.effect + "/" + p.rival);
  EXPECT_EQ(names, (std::vector<std::string>{"asymmetry/saturation", "creep/drift", "creep/offset"}));
}

TEST(StartupTransient, AnErrorInTheFirstPeriodAfterARestIsNamedWithItsWarmUp) {
  std::vector<double> u;
  hold(u, 0.0, 1.0);
  sine(u, 2.0, 50.0, 5.0);  // ten periods of 500 samples after 1000 at rest
  const ExcitationContent c = of(u);
  Eigen::VectorXd e = Eigen::VectorXd::Constant(Eigen::Index(u.size()), 0.01);
  e.segment(1000, 500).setConstant(0.2);  // the first period after the rest
  const StartupTransient t = find_startup_transient(e, c);
  EXPECT_TRUE(t.dominates);
  // The rest ends where the sine leaves 2 % of its range, a few samples in.
  EXPECT_NEAR(double(t.warmup), 1500.0, 5.0);
  EXPECT_NEAR(t.sample_share, 500.0 / 6000.0, 1e-3);
  EXPECT_NE(t.sentence().find("--warmup " + std::to_string(t.warmup)), std::string::npos) << t.sentence();
  // The same error spread over the record is no transient.
  EXPECT_FALSE(find_startup_transient(Eigen::VectorXd::Constant(Eigen::Index(u.size()), 0.01), c).dominates);
}

TEST(StartupTransient, TheAdvisedWarmUpWaitsForARingingErrorToSettle) {
  std::vector<double> u;
  hold(u, 0.0, 1.0);
  sine(u, 2.0, 50.0, 5.0);  // periods of 500 samples from about sample 1000
  const ExcitationContent c = of(u);
  ASSERT_FALSE(c.parts.empty());
  const Eigen::Index start = c.parts.front().begin;
  // A resonance that rings on for four periods past the first, at 20 Hz and
  // decaying by e every 400 samples, over a floor of 0.01: its envelope
  // falls below twice the floor's block RMS (2 * 0.01) about 400 * ln(0.5 /
  // 0.02) = 1288 samples after the part's start.
  Eigen::VectorXd e = Eigen::VectorXd::Constant(Eigen::Index(u.size()), 0.01);
  for (Eigen::Index k = start; k < start + 2500; ++k) {
    const double s = double(k - start);
    e(k) += 0.5 * std::exp(-s / 400.0) * std::sin(2 * M_PI * 20.0 * s * kTs);
  }
  const StartupTransient t = find_startup_transient(e, c);
  EXPECT_TRUE(t.dominates);
  EXPECT_NEAR(double(t.first_period_end), double(start + 500), 2.0);
  EXPECT_GT(t.warmup, start + 1000);
  EXPECT_LT(t.warmup, start + 1600);
  EXPECT_NE(t.sentence().find("--warmup " + std::to_string(t.warmup) + " (where the error"), std::string::npos)
      << t.sentence();
  // A first part whose error falls only in its second half is wrong there,
  // not starting up: the advice is its first period, not the fall.
  std::vector<double> two;
  hold(two, 0.0, 1.0);
  sine(two, 2.0, 50.0, 6.0);
  hold(two, 0.0, 1.0);
  sine(two, 2.0, 50.0, 4.0);
  const ExcitationContent c2 = of(two);
  ASSERT_EQ(c2.parts.size(), 2u);
  Eigen::VectorXd e2 = Eigen::VectorXd::Constant(Eigen::Index(two.size()), 0.01);
  e2.segment(c2.parts[0].begin, 3500).setConstant(0.2);  // past half of its 6 000 samples
  const StartupTransient late = find_startup_transient(e2, c2);
  EXPECT_NEAR(double(late.warmup), double(c2.parts[0].begin + 500), 2.0);
  EXPECT_EQ(late.warmup, late.first_period_end);
  // Falling within the first half, the same error is a transient.
  e2.segment(c2.parts[0].begin + 2000, 1500).setConstant(0.01);
  EXPECT_NEAR(double(find_startup_transient(e2, c2).warmup), double(c2.parts[0].begin + 2000), 250.0);
}

TEST(StartupTransient, ARecordThatStartsAtALevelTheModelMissesIsNamedWithTheHeldStart) {
  std::vector<double> u;
  sine(u, 0.5, 50.0, 5.0);  // 2.5 periods of 2 000 samples: the periodic rule cannot single out the start
  const ExcitationContent c = of(u);
  const Eigen::Index n = Eigen::Index(u.size());
  // The model starts at 0, the record at 1, and the two meet after 200
  // samples; the rest fits to 0.05. The first period holds 40 % of the
  // samples, so only the level at the start names it.
  Eigen::VectorXd e(n);
  for (Eigen::Index k = 0; k < n; ++k) e[k] = 0.05 * std::sin(0.37 * double(k)) + std::max(0.0, 1.0 - k / 200.0);
  const StartupTransient t = find_startup_transient(e, c);
  EXPECT_FALSE(t.dominates);
  EXPECT_TRUE(t.starts_away);
  EXPECT_GT(t.start_ratio, kStartLevelRatio);
  EXPECT_NE(t.sentence().find("The record starts away from where the model starts"), std::string::npos);
  EXPECT_NE(t.sentence().find("--warmup N --initial-state held"), std::string::npos) << t.sentence();
  // An error as large at the start but oscillating about zero is no level.
  for (Eigen::Index k = 0; k < 50; ++k) e[k] = (k % 2 ? 1.0 : -1.0);
  EXPECT_FALSE(find_startup_transient(e, c).starts_away);
  // Nor is one the size of the record's own error.
  EXPECT_FALSE(find_startup_transient(Eigen::VectorXd::Constant(n, 0.3), c).starts_away);
}

}  // namespace
}  // namespace hystbench
