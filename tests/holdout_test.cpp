// Which samples a discovery fit may not see (framework/model/holdout).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "framework/core/error.hpp"
#include "framework/model/holdout.hpp"

namespace hystbench {
namespace {

// Sine segments at the given frequencies, `seconds` each, 1 kHz.
ModelData sines(const std::vector<double>& frequencies, double seconds = 1.0) {
  Measurement m;
  const int per = int(seconds * 1000);
  const int n = per * int(frequencies.size());
  m.sample_time = 1e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3 * (n - 1));
  m.u.resize(n);
  m.y = Eigen::VectorXd::Zero(n);
  for (int s = 0; s < int(frequencies.size()); ++s)
    for (int k = 0; k < per; ++k) {
      m.u[s * per + k] = std::sin(2 * M_PI * frequencies[s] * k * 1e-3 + 0.1);
      m.segment.push_back("f" + std::to_string(int(frequencies[s])));
    }
  return ModelData(m, {});
}

std::set<std::string> held_segments(const ModelData& d) {
  std::set<std::string> out;
  for (Eigen::Index k = 0; k < d.size(); ++k)
    if (d.estimation[k] == 0.0) out.insert(d.segment[k]);
  return out;
}

TEST(Holdout, AutoHoldsOutTheLastQuarterOfEverySegment) {
  // Every frequency stays in both parts, whatever the number of segments.
  for (const auto& f : {std::vector<double>{1, 5}, std::vector<double>{10, 1, 50, 2, 20, 5}}) {
    ModelData d = sines(f);
    apply_holdout(d, HoldoutSpec{});
    for (Eigen::Index k = 0; k < d.size(); ++k)
      ASSERT_EQ(d.estimation[k], (k % 1000) >= 750 ? 0.0 : 1.0) << k;
    EXPECT_EQ(held_segments(d).size(), f.size());
    EXPECT_NE(describe_holdout(d, HoldoutSpec{}).find("last quarter of every segment"),
              std::string::npos);
  }
}

TEST(Holdout, AutoWithoutSegmentsHoldsOutTheTailOfEachEighth) {
  ModelData d = sines({1, 5});
  d.segment.clear();
  apply_holdout(d, HoldoutSpec{});
  // 2000 samples in blocks of 250: samples 188..249 of each are held out
  // (floor(0.25 * 250) = 62).
  for (Eigen::Index k = 0; k < d.size(); ++k)
    ASSERT_EQ(d.estimation[k], (k % 250) >= 188 ? 0.0 : 1.0) << k;
}

TEST(Holdout, ByFrequencySpreadsHeldOutSegmentsOverTheBand) {
  // Time order is not frequency order: the choice must follow frequency.
  ModelData d = sines({10, 1, 50, 2, 20, 5});
  apply_holdout(d, HoldoutSpec::parse("by-frequency"));
  // Ranks by frequency 1,2,5,10,20,50: a quarter of six rounds to two, held
  // at the inner ranks 1 and 4, i.e. 2 Hz and 20 Hz.
  EXPECT_EQ(held_segments(d), (std::set<std::string>{"f2", "f20"}));
  EXPECT_EQ(d.heldout_count(), 2000);
  EXPECT_NE(describe_holdout(d, HoldoutSpec::parse("by-frequency")).find("f2, f20"),
            std::string::npos);
}

TEST(Holdout, ByFrequencyNeverHoldsOutTheHighestFrequency) {
  ModelData d = sines({1, 2, 5, 10});
  apply_holdout(d, HoldoutSpec::parse("by-frequency"));
  EXPECT_EQ(held_segments(d), (std::set<std::string>{"f5"}));
  EXPECT_EQ(HoldoutSpec::parse("by-frequency").text(), "by-frequency");
}

TEST(Holdout, ExplicitFormsAndNone) {
  ModelData d = sines({1, 2, 5, 10});
  apply_holdout(d, HoldoutSpec::parse("segments:f1,f10"));
  EXPECT_EQ(held_segments(d), (std::set<std::string>{"f1", "f10"}));
  apply_holdout(d, HoldoutSpec::parse("last:0.1"));
  EXPECT_EQ(d.heldout_count(), 400);
  apply_holdout(d, HoldoutSpec::parse("none"));
  EXPECT_EQ(d.heldout_count(), 0);
  EXPECT_EQ(HoldoutSpec::parse("last:0.1").text(), "last:0.1");
}

TEST(Holdout, BadSpecsSayWhatIsAccepted) {
  try {
    HoldoutSpec::parse("half");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("auto, none, last:FRACTION"), std::string::npos);
  }
  EXPECT_THROW(HoldoutSpec::parse("last:1.5"), InputError);
  ModelData d = sines({1, 2, 5, 10});
  try {
    apply_holdout(d, HoldoutSpec::parse("segments:f3"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no segment 'f3'"), std::string::npos);
  }
  EXPECT_THROW(apply_holdout(d, HoldoutSpec::parse("segments:f1,f2,f5,f10")), InputError);
}

}  // namespace
}  // namespace hystbench
