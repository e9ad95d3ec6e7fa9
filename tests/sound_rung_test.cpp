// Which rung propose extends (framework/discovery/sound_rung.hpp): the last
// one before the first added effect the data do not support, on ladders
// built by hand so that the answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "framework/discovery/sound_rung.hpp"

namespace hystbench {
namespace {

constexpr double kTs = 1e-3;

// A record of one sine, or of two sines a decade apart.
ExcitationContent excitation(bool two_frequencies) {
  std::vector<double> u;
  for (double hz : two_frequencies ? std::vector<double>{1.0, 10.0} : std::vector<double>{1.0})
    for (int k = 0; k < 5000; ++k) u.push_back(75.0 * std::sin(2 * M_PI * hz * k * kTs));
  return describe_excitation(Eigen::Map<const Eigen::VectorXd>(u.data(), Eigen::Index(u.size())), {}, kTs, "V");
}

// A rung of `effects` that took on `added`; `on_bound` names a parameter of
// `added` on a bound of its search range ("" for none).
void climb(Ladder& l, const std::string& effects, const std::string& added, const std::string& on_bound,
           const ExcitationContent& e) {
  LadderStep s{Model::parse(effects), {}, {}};
  s.added = added;
  Diagnosis d{s.model, {}, {}};
  for (const auto& name : s.model.effects()) {
    EffectCheck c;
    c.effect = name;
    if (name == added && !on_bound.empty()) c.at_bound.push_back(on_bound);
    d.check.effects.push_back(c);
  }
  d.where.excitation = e;
  l.steps.push_back(s);
  l.diagnoses.push_back(d);
}

TEST(SoundRung, ALadderWhoseAdditionsAreSupportedIsExtendedAtItsLastRung) {
  Ladder l;
  const auto wide = excitation(true);
  climb(l, "msd", "", "", wide);
  climb(l, "hysteresis,msd", "hysteresis", "", wide);
  climb(l, "hysteresis,msd,offset", "offset", "", wide);
  const SoundRung r = sound_rung(l);
  EXPECT_EQ(r.step, 2u);
  EXPECT_EQ(r.model, "hysteresis,msd,offset");
  EXPECT_TRUE(r.doubtful.empty());
  EXPECT_EQ(r.fit_file(), "step_2/fit.json");
}

TEST(SoundRung, AnAdditionWithAParameterOnABoundSendsProposeToTheRungBefore) {
  Ladder l;
  const auto wide = excitation(true);
  climb(l, "msd", "", "", wide);
  climb(l, "hysteresis,msd", "hysteresis", "", wide);
  climb(l, "hysteresis,msd,creep", "creep", "creep.tau", wide);
  climb(l, "hysteresis,msd,creep,offset", "offset", "", wide);
  const SoundRung r = sound_rung(l);
  EXPECT_EQ(r.step, 1u);
  EXPECT_EQ(r.doubtful, "creep");
  const std::string s = r.sentence();
  EXPECT_NE(s.find("step 2 took on creep"), std::string::npos) << s;
  EXPECT_NE(s.find("creep.tau sits on a bound"), std::string::npos) << s;
  EXPECT_EQ(r.to_json()["fit"], "step_1/fit.json");
}

TEST(SoundRung, AnAdditionTheRecordCannotTellFromARivalIsDoubtful) {
  // At one frequency hysteresis and msd draw the same ellipse.
  Ladder one;
  climb(one, "msd", "", "", excitation(false));
  climb(one, "hysteresis,msd", "hysteresis", "", excitation(false));
  const SoundRung r = sound_rung(one);
  EXPECT_EQ(r.step, 0u);
  EXPECT_NE(r.why.find("cannot tell it from msd"), std::string::npos) << r.why;
  // Two frequencies a decade apart tell them apart.
  Ladder two;
  climb(two, "msd", "", "", excitation(true));
  climb(two, "hysteresis,msd", "hysteresis", "", excitation(true));
  EXPECT_EQ(sound_rung(two).step, 1u);
}

TEST(SoundRung, AnAdditionDroppedAgainTookNothingOn) {
  Ladder l;
  const auto wide = excitation(true);
  climb(l, "msd", "", "", wide);
  climb(l, "msd", "creep", "", wide);  // creep was dropped again: not in the rung's model
  EXPECT_EQ(sound_rung(l).step, 1u);
}

TEST(SoundRung, ALadderThatAddedNothingIsExtendedAtItsStart) {
  Ladder l;
  climb(l, "msd", "", "", excitation(true));
  const SoundRung r = sound_rung(l);
  EXPECT_EQ(r.step, 0u);
  EXPECT_NE(r.sentence().find("the start model"), std::string::npos) << r.sentence();
}

}  // namespace
}  // namespace hystbench
