// trials.jsonl read back: what a crash can leave (a last line cut short) is
// tolerated only where asked for, and anything else malformed is refused
// with the file and line.
#include <gtest/gtest.h>

#include "framework/core/error.hpp"
#include "framework/harness/trial_log.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {
using test_support::contains;

std::string line_of(long trial) {
  TrialResult r;
  r.label = "DE";
  r.trial = trial;
  r.best = 1.5;
  r.stop = StopReason::Evaluations;
  r.trace = {{10, 1.5}};
  return r.to_json().dump() + "\n";
}

std::string refusal(const std::filesystem::path& file, bool tolerate) {
  try {
    read_trial_log(file, tolerate);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TrialLogRead, TornLastLineIsDroppedOnlyWhenTolerated) {
  test_support::TempDir dir;
  const std::string torn = line_of(2).substr(0, 40);
  const auto file = dir.write("trials.jsonl", line_of(0) + line_of(1) + torn);
  const auto contents = read_trial_log(file, /*tolerate_torn_end=*/true);
  ASSERT_EQ(contents.trials.size(), 2u);
  EXPECT_EQ(contents.trials[1].trial, 1);
  EXPECT_EQ(contents.torn_line, 3);
  const std::string strict = refusal(file, false);
  EXPECT_TRUE(contains(strict, "trials.jsonl line 3: not a trial record")) << strict;
}

TEST(TrialLogRead, CompleteLastLineWithoutNewlineIsKept) {
  test_support::TempDir dir;
  std::string last = line_of(1);
  last.pop_back();
  const auto contents = read_trial_log(dir.write("trials.jsonl", line_of(0) + last), true);
  EXPECT_EQ(contents.trials.size(), 2u);
  EXPECT_FALSE(contents.torn_line);
}

TEST(TrialLogRead, BadLineInTheMiddleIsRefusedEvenWhenTolerant) {
  test_support::TempDir dir;
  const auto file = dir.write("trials.jsonl", line_of(0) + "{\"label\": \n" + line_of(2));
  const std::string message = refusal(file, true);
  EXPECT_TRUE(contains(message, "trials.jsonl line 2: not a trial record")) << message;
}

TEST(TrialLogRead, AppendedLinesReadBackBitForBit) {
  test_support::TempDir dir;
  TrialResult r;
  r.label = "PSO";
  r.trial = 4;
  r.best = 0.1 + 0.2;
  r.stop = StopReason::Failed;
  r.message = "deliberate";
  {
    TrialLog log(dir.path() / "trials.jsonl");
    log.append(r);
  }
  const auto back = read_trial_log(dir.path() / "trials.jsonl").trials.at(0);
  EXPECT_EQ(back.best, r.best);
  EXPECT_EQ(back.message, "deliberate");
  EXPECT_TRUE(back.failed());
}

}  // namespace
}  // namespace hystbench
