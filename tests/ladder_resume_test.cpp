// discover --resume (framework/discovery/ladder_checkpoint): a ladder stopped
// after a step and resumed from its checkpoint ends exactly where the
// uninterrupted run ends, and a checkpoint made with other options is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "framework/core/error.hpp"
#include "framework/discovery/ladder_checkpoint.hpp"
#include "framework/discovery/ladder_report.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/model/holdout.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

const nlohmann::json kExcitation = {
    {"sample_rate", 500},
    {"segments",
     {{{"type", "sine"}, {"frequency", 2}, {"amplitude", 50}, {"duration", 2}},
      {{"type", "sine"}, {"frequency", 9}, {"amplitude", 60}, {"duration", 2}}}}};

// Two output effects hidden behind a gain: a ladder of two additions.
ModelData two_step_data() {
  const Model truth = Model::parse("offset,drift");
  const SyntheticData s = make_model_synthetic_data(
      truth, {{"gain", 0.5}, {"offset.c0", 3.0}, {"drift.c1", 2.0}}, kExcitation, 0.01, 5, "resume");
  ModelData d(s.data, SignalScales::of(s.data));
  apply_holdout(d, HoldoutSpec{});
  return d;
}

DiscoverOptions quick_options() {
  DiscoverOptions o;
  o.diagnose.fit.restarts = 1;
  o.diagnose.fit.evaluations = 2000;
  o.diagnose.fit.local_evaluations = 600;
  o.diagnose.fit.seed = 3;
  o.diagnose.candidates = {"offset", "drift", "delay"};
  return o;
}

const nlohmann::json kContext = {{"options", "quick"}};

struct Stop : std::runtime_error {
  Stop() : std::runtime_error("stopped") {}
};

TEST(LadderResume, StoppedAfterAStepAndResumedGivesTheSameLadder) {
  const ModelData data = two_step_data();
  const DiscoverOptions o = quick_options();
  const Ladder whole = discover(Model::parse("none"), data, o);
  ASSERT_GE(whole.steps.size(), 3u) << "the case must climb at least two rungs";

  test_support::TempDir dir;
  // Stopped right after step 1 was diagnosed, its checkpoint written.
  EXPECT_THROW(discover(Model::parse("none"), data, o,
                        [&](const Ladder& so_far) {
                          std::ofstream(dir.path() / "checkpoint.json")
                              << checkpoint_json(so_far, kContext).dump(1);
                          if (so_far.diagnoses.size() == 2) throw Stop();
                        }),
               Stop);
  Ladder restored = read_checkpoint(dir.path(), kContext, data, o);
  EXPECT_EQ(restored.restored, 2u);
  const Ladder resumed = resume_discover(std::move(restored), data, o);

  ASSERT_EQ(resumed.steps.size(), whole.steps.size());
  for (std::size_t k = 0; k < whole.steps.size(); ++k) {
    EXPECT_EQ(resumed.steps[k].model.text(), whole.steps[k].model.text()) << k;
    EXPECT_EQ(resumed.steps[k].x, whole.steps[k].x) << k;  // bit for bit
    EXPECT_EQ(resumed.steps[k].added, whole.steps[k].added) << k;
    EXPECT_EQ(resumed.diagnoses[k].verdict, whole.diagnoses[k].verdict) << k;
  }
  // Everything ladder.json says, the restored steps' optimum checks and
  // close calls included.
  const DataSource source;
  const HoldoutSpec holdout;
  const LadderContext ctx{data, source, holdout, std::nullopt, {}};
  EXPECT_EQ(ladder_json(resumed, ctx).dump(), ladder_json(whole, ctx).dump());
}

TEST(LadderResume, ACheckpointOfOtherOptionsIsRefusedNamingTheKey) {
  const ModelData data = two_step_data();
  test_support::TempDir dir;
  Ladder ladder;
  ladder.steps.push_back({Model::parse("none"), Model::parse("none").neutral(), {}});
  ladder.diagnoses.push_back({Model::parse("none"), Model::parse("none").neutral(), {}});
  ladder.diagnoses.back().verdict = "none";
  std::ofstream(dir.path() / "checkpoint.json")
      << checkpoint_json(ladder, {{"fit", {{"seed", 1}}}}).dump(1);
  try {
    read_checkpoint(dir.path(), {{"fit", {{"seed", 2}}}}, data, quick_options());
    FAIL() << "a checkpoint of another seed was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another fit.seed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_checkpoint(dir.path() / "missing", {}, data, quick_options()), InputError);
}

}  // namespace
}  // namespace hystbench
