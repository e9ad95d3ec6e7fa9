// Interrupted campaigns: Ctrl-C stops with exit 130 and says how to resume,
// `kill -9` loses no finished trial, a torn last line is dropped with a
// warning, and `run --resume` runs only the missing trials and gives the
// summary of an uninterrupted run. A folder of another run is refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;
using test_support::contains;
using test_support::hystbench;
using test_support::read;

// Two algorithms x 12 trials on the bundled data: long enough (a second or
// two) to be stopped midway, short enough for a test.
std::string experiment_text(long evaluations) {
  return R"({"name": "resume", "problem": {"type": "hammerstein", "data": ")" HYSTBENCH_SOURCE_DIR
         R"(/problems/hammerstein/data/default.csv"}, "budget": {"evaluations": )" +
         std::to_string(evaluations) + R"(}, "trials": 12, "seed": 7, "algorithms": [
         {"name": "de", "label": "DE", "params": {"np": 20}},
         {"name": "pso", "label": "PSO", "params": {"swarm": 20}}]})";
}

nlohmann::json summary_numbers(const fs::path& dir) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
  j.erase("provenance");
  for (auto& a : j["algorithms"]) a.erase("wall_seconds");
  return j;
}

// Every trial line without its wall time, in (label, trial) order.
std::vector<nlohmann::json> trials_of(const fs::path& dir) {
  std::vector<nlohmann::json> out;
  std::ifstream in(dir / "trials.jsonl");
  for (std::string line; std::getline(in, line);) {
    auto j = nlohmann::json::parse(line);
    j.erase("wall_seconds");
    out.push_back(j);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return std::make_pair(a["algorithm_index"].template get<int>(), a["trial"].template get<long>()) <
           std::make_pair(b["algorithm_index"].template get<int>(), b["trial"].template get<long>());
  });
  return out;
}

long lines_in(const fs::path& file) {
  const std::string text = read(file);
  return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// `hystbench ARGS` started in the background, output into `log`.
pid_t start(const std::string& args, const fs::path& log) {
  const std::string command = "exec " + std::string(HYSTBENCH_EXE) + " " + args + " > " + log.string() + " 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// Waits until `file` holds at least `lines` lines (or the process ended).
void wait_for_lines(pid_t pid, const fs::path& file, long lines) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (lines_in(file) < lines && std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) FAIL() << "the run ended before it could be stopped";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

int stop_and_wait(pid_t pid, int signal) {
  kill(pid, signal);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

class Resume : public ::testing::Test {
 protected:
  void SetUp() override {
    experiment_ = temp_.write("resume.json", experiment_text(1500)).string();
    const auto full = hystbench("run " + experiment_ + " --threads 2 --out " + dir("full"));
    ASSERT_EQ(full.code, 0) << full.output;
  }
  std::string dir(const std::string& name) const { return (temp_.path() / name).string(); }
  // Resumes `name` and checks it ends as the uninterrupted run did.
  void expect_resumed_like_full(const std::string& name) {
    const auto resumed = hystbench("run " + experiment_ + " --threads 2 --out " + dir(name) + " --resume");
    ASSERT_EQ(resumed.code, 0) << resumed.output;
    EXPECT_TRUE(contains(resumed.output, "resuming:")) << resumed.output;
    EXPECT_EQ(summary_numbers(dir(name)), summary_numbers(dir("full")));
    EXPECT_EQ(trials_of(dir(name)), trials_of(dir("full")));
    EXPECT_EQ(read(fs::path(dir(name)) / "table.csv"), read(fs::path(dir("full")) / "table.csv"));
  }

  test_support::TempDir temp_;
  std::string experiment_;
};

TEST_F(Resume, AfterKillNineRunsOnlyTheMissingTrials) {
  const pid_t pid = start("run " + experiment_ + " --threads 1 --out " + dir("killed"), temp_.path() / "killed.log");
  wait_for_lines(pid, fs::path(dir("killed")) / "trials.jsonl", 3);
  stop_and_wait(pid, SIGKILL);
  const long kept = lines_in(fs::path(dir("killed")) / "trials.jsonl");
  ASSERT_LT(kept, 24) << "the run finished before it was killed";
  EXPECT_FALSE(fs::exists(fs::path(dir("killed")) / "summary.json"));

  const auto again = hystbench("run " + experiment_ + " --out " + dir("killed"));
  EXPECT_EQ(again.code, 2);
  EXPECT_TRUE(contains(again.output, "pass --resume")) << again.output;
  expect_resumed_like_full("killed");
}

TEST_F(Resume, CtrlCKeepsFinishedTrialsExitsWith130AndSaysHowToResume) {
  const fs::path log = temp_.path() / "interrupted.log";
  const pid_t pid = start("run " + experiment_ + " --threads 2 --out " + dir("interrupted"), log);
  wait_for_lines(pid, fs::path(dir("interrupted")) / "trials.jsonl", 2);
  EXPECT_EQ(stop_and_wait(pid, SIGINT), 130) << read(log);
  const std::string said = read(log);
  EXPECT_TRUE(contains(said, "interrupted: ")) << said;
  EXPECT_TRUE(contains(said, "--out " + dir("interrupted") + " --resume")) << said;
  const std::string trials = read(fs::path(dir("interrupted")) / "trials.jsonl");
  ASSERT_FALSE(trials.empty());
  EXPECT_EQ(trials.back(), '\n') << "a line was torn by Ctrl-C";
  expect_resumed_like_full("interrupted");
}

TEST_F(Resume, TornLastLineIsDroppedWithAWarning) {
  const fs::path torn = dir("torn");
  fs::create_directories(torn);
  fs::copy_file(fs::path(dir("full")) / "campaign.json", torn / "campaign.json");
  std::ifstream in(fs::path(dir("full")) / "trials.jsonl");
  std::ofstream out(torn / "trials.jsonl", std::ios::binary);
  std::string line;
  for (int i = 0; i < 5 && std::getline(in, line); ++i) out << line << "\n";
  std::getline(in, line);
  out << line.substr(0, line.size() / 2);  // a crash in the middle of an append
  out.close();

  const auto resumed = hystbench("run " + experiment_ + " --out " + torn.string() + " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_TRUE(contains(resumed.output, "warning: " + (torn / "trials.jsonl").string() + " line 6: cut short"))
      << resumed.output;
  EXPECT_TRUE(contains(resumed.output, "resuming: 5 finished, 19 to run")) << resumed.output;
  EXPECT_EQ(summary_numbers(torn), summary_numbers(dir("full")));
  EXPECT_EQ(trials_of(torn), trials_of(dir("full")));
}

TEST_F(Resume, CompleteFolderRunsNothingAndRewritesTheSameSummary) {
  const auto resumed = hystbench("run " + experiment_ + " --out " + dir("full") + " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_TRUE(contains(resumed.output, "resuming: 24 finished, 0 to run")) << resumed.output;
  EXPECT_EQ(lines_in(fs::path(dir("full")) / "trials.jsonl"), 24);
}

TEST_F(Resume, RefusesAFolderOfAnotherRunNamingTheField) {
  const std::string before = read(fs::path(dir("full")) / "trials.jsonl");
  const auto seed = hystbench("run " + experiment_ + " --seed 8 --out " + dir("full") + " --resume");
  EXPECT_EQ(seed.code, 2);
  EXPECT_TRUE(contains(seed.output, "--resume: experiment.seed differs between")) << seed.output;

  const auto other = temp_.write("other.json", experiment_text(1600)).string();
  const auto budget = hystbench("run " + other + " --out " + dir("full") + " --resume");
  EXPECT_EQ(budget.code, 2);
  EXPECT_TRUE(contains(budget.output, "experiment.budget.evaluations differs")) << budget.output;

  const auto slice = hystbench("run " + experiment_ + " --trial-range 0:6 --out " + dir("full") + " --resume");
  EXPECT_EQ(slice.code, 2);
  EXPECT_TRUE(contains(slice.output, "trial_range differs")) << slice.output;
  EXPECT_EQ(read(fs::path(dir("full")) / "trials.jsonl"), before) << "a refused resume changed the trials";
}

}  // namespace
}  // namespace hystbench
