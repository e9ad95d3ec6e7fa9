// The `hystbench` program as a user runs it: results, determinism across
// thread counts, and bad input answered with one clear message and exit 2.
#include <gtest/gtest.h>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace fs = std::filesystem;

namespace {

using hystbench::test_support::hystbench;
using hystbench::test_support::Outcome;

class Cli : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) { return temp_.write(name, text).string(); }
  // An experiment on `data` with one DE entry whose fields are `algorithm`.
  std::string experiment(const std::string& data, const std::string& algorithm = R"("name": "de")",
                         const std::string& budget = R"({"evaluations": 600})", int trials = 4) {
    return write("experiment.json", R"({"name": "t", "problem": {"type": "hammerstein", "data": ")" + data +
                                        R"("}, "budget": )" + budget + R"(, "trials": )" +
                                        std::to_string(trials) + R"(, "seed": 3, "algorithms": [{)" +
                                        algorithm + "}]}");
  }
  static std::string default_data() { return std::string(HYSTBENCH_SOURCE_DIR) + "/problems/hammerstein/data/default.csv"; }

  hystbench::test_support::TempDir temp_;
  const fs::path& dir_ = temp_.path();
};

nlohmann::json numbers_of(const fs::path& summary) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(summary));
  j.erase("provenance");  // date, host, thread count
  for (auto& a : j["algorithms"]) a.erase("wall_seconds");
  return j;
}

// Every trial line without its wall time, sorted: finishing order varies
// with threads, nothing else may.
std::vector<nlohmann::json> sorted_trials(const fs::path& file) {
  std::vector<nlohmann::json> out;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    auto j = nlohmann::json::parse(line);
    j.erase("wall_seconds");
    out.push_back(j);
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.dump() < y.dump(); });
  return out;
}

TEST_F(Cli, SummaryNumbersDoNotDependOnThreadCount) {
  const auto exp = experiment(default_data(), R"("name": "de", "label": "DE", "params": {"np": 30})");
  const auto one = hystbench("run " + exp + " --threads 1 --out " + (dir_ / "one").string());
  ASSERT_EQ(one.code, 0) << one.output;
  const auto two = hystbench("run " + exp + " --threads 2 --out " + (dir_ / "two").string());
  ASSERT_EQ(two.code, 0) << two.output;
  const auto again = hystbench("run " + exp + " --threads 2 --out " + (dir_ / "again").string());
  ASSERT_EQ(again.code, 0) << again.output;
  const auto a = numbers_of(dir_ / "one" / "summary.json");
  EXPECT_EQ(a, numbers_of(dir_ / "two" / "summary.json"));
  EXPECT_EQ(a, numbers_of(dir_ / "again" / "summary.json"));
  const auto trials = sorted_trials(dir_ / "one" / "trials.jsonl");
  EXPECT_EQ(trials.size(), 4u);
  EXPECT_EQ(trials, sorted_trials(dir_ / "two" / "trials.jsonl"));
  EXPECT_EQ(trials, sorted_trials(dir_ / "again" / "trials.jsonl"));
  for (const char* table : {"table.csv", "stats.csv", "convergence.csv"})
    EXPECT_EQ(hystbench::test_support::read(dir_ / "one" / table),
              hystbench::test_support::read(dir_ / "two" / table)) << table;
  EXPECT_EQ(a["algorithms"][0]["trials"], 4);
  EXPECT_TRUE(a["algorithms"][0]["best_x"].contains("alpha"));
  for (const char* f : {"trials.jsonl", "table.md", "table.tex", "table.csv", "convergence.csv", "convergence.gp",
                        "fit_DE_time.gp", "fit_DE_loops.gp"})
    EXPECT_TRUE(fs::exists(dir_ / "one" / f)) << f;
  EXPECT_NE(one.output.find("| DE |"), std::string::npos) << one.output;
}

TEST_F(Cli, RefusesToOverwriteResultsWithoutForce) {
  const auto exp = experiment(default_data(), R"("name": "de")", R"({"evaluations": 100})", 1);
  const auto out = " --out " + (dir_ / "r").string();
  ASSERT_EQ(hystbench("run " + exp + out).code, 0);
  const auto again = hystbench("run " + exp + out);
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.output.find("already holds results; pass --resume to run only the missing trials, --force"), std::string::npos) << again.output;
  EXPECT_EQ(hystbench("run " + exp + out + " --force").code, 0);
}

// Each bad input: exit code 2, a message with the place, and no results folder.
void expect_rejected(const Outcome& o, const std::vector<std::string>& fragments, const fs::path& out) {
  EXPECT_EQ(o.code, 2) << o.output;
  for (const auto& f : fragments) EXPECT_NE(o.output.find(f), std::string::npos) << "missing '" << f << "' in: " << o.output;
  EXPECT_FALSE(fs::exists(out)) << "partial output left in " << out;
}

TEST_F(Cli, MissingColumnNamesFileAndColumns) {
  const auto csv = write("nocol.csv", "t,u,z\n0,1,2\n0.1,2,3\n0.2,3,4\n");
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + experiment(csv) + " --out " + out.string()),
                  {"nocol.csv", "'y'", "--columns"}, out);
}

TEST_F(Cli, NanValueNamesFileLineAndColumn) {
  const auto csv = write("nan.csv", "t,u,y\n0,1,2\n0.1,nan,3\n0.2,3,4\n");
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + experiment(csv) + " --out " + out.string()), {"nan.csv", "line 3", "'u'"}, out);
}

TEST_F(Cli, TimeNotIncreasingNamesFileAndLine) {
  const auto csv = write("time.csv", "t,u,y\n0,1,2\n0.1,2,3\n0.1,3,4\n0.3,3,4\n");
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + experiment(csv) + " --out " + out.string()), {"time.csv", "line 4"}, out);
}

TEST_F(Cli, UnknownAlgorithmNamesKeyAndKnownOnes) {
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + experiment(default_data(), R"("name": "sade")") + " --out " + out.string()),
                  {"experiment.json", "algorithms[0].name", "unknown name 'sade'", "known: ", " de,", "cmaes"}, out);
}

TEST_F(Cli, UnknownParameterNamesKeyAndValidOnes) {
  const auto out = dir_ / "o";
  expect_rejected(
      hystbench("run " + experiment(default_data(), R"("name": "de", "params": {"F": 0.5})") + " --out " + out.string()),
      {"experiment.json", "algorithms[0] (de).params", "unknown key 'F'", "valid keys: np, f, cr"}, out);
}

TEST_F(Cli, OutOfRangeParameterNamesTheRange) {
  const auto out = dir_ / "o";
  expect_rejected(
      hystbench("run " + experiment(default_data(), R"("name": "de", "params": {"np": 2})") + " --out " + out.string()),
      {"params.np = 2 is out of range; it must be in [4, 100000]"}, out);
}

TEST_F(Cli, BrokenJsonNamesFileAndPosition) {
  const auto exp = write("broken.json", "{\"name\": \"t\",\n \"trials\": 3,,\n}");
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + exp + " --out " + out.string()), {"broken.json", "not valid JSON", "line 2"}, out);
}

TEST_F(Cli, NegativeBudgetIsRejected) {
  const auto out = dir_ / "o";
  expect_rejected(hystbench("run " + experiment(default_data(), R"("name": "de")", R"({"evaluations": -5})") +
                            " --out " + out.string()),
                  {"budget.evaluations = -5: must be a positive integer"}, out);
}

TEST_F(Cli, SimulateWritesDataAndTruthWithConsistentNoiseFloor) {
  const auto params = write("p.json", R"({"alpha": 0.4, "beta": 0.0015, "gamma": 0.0005, "L": 0.2, "d1": 0.15,
    "d2": 6e-5, "M": 1.583e-05, "D": 0.001194, "K": 1.0, "a": 0.2, "b": 0.09, "c": -1.0, "d": 0.29})");
  const auto excitation = write("e.json", R"({"sample_rate": 1000, "segments": [
    {"type": "sine", "frequency": 2, "amplitude": 500, "duration": 1},
    {"type": "sweep", "f0": 1, "f1": 20, "amplitude": 300, "offset": 100, "duration": 1},
    {"type": "steps", "levels": [0, 400, 100], "hold": 0.2, "ramp": 0.05}]})");
  const auto csv = (dir_ / "sim.csv").string();
  const auto o = hystbench("simulate --params " + params + " --excitation " + excitation + " --noise 0.02 --seed 9 --out " + csv);
  ASSERT_EQ(o.code, 0) << o.output;
  const auto truth = nlohmann::json::parse(std::ifstream(dir_ / "sim.truth.json"));
  EXPECT_EQ(truth["samples"], 1000 + 1000 + 3 * 250);
  // The noise floor is the SSE of the truth; it is close to N sigma^2.
  EXPECT_NEAR(truth["noise_floor_sse"].get<double>() / truth["expected_noise_sse"].get<double>(), 1.0, 0.1);
  std::ifstream in(csv);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  EXPECT_NE(last.find(",steps"), std::string::npos) << last;
}

TEST_F(Cli, ListShowsOptimizersWithParametersAndCitations) {
  const auto o = hystbench("list");
  EXPECT_EQ(o.code, 0);
  for (const char* s : {"de - ", "np: integer in [4, 100000], default auto", "Storn", "hammerstein", "function"})
    EXPECT_NE(o.output.find(s), std::string::npos) << s;
}

TEST_F(Cli, BadCommandLineExitsWithTwo) {
  EXPECT_EQ(hystbench("run").code, 2);
  EXPECT_EQ(hystbench("frobnicate").code, 2);
  EXPECT_EQ(hystbench("run --help").code, 0);
}

TEST_F(Cli, MistypedCommandIsNamedWithTheClosestOne) {
  const auto typo = hystbench("discovr --data d.csv --out x");
  EXPECT_EQ(typo.code, 2);
  EXPECT_EQ(typo.output, "hystbench: error: unknown command 'discovr'; did you mean 'discover'? "
                         "(hystbench --help lists the commands)\n");
  // Two neighbours swapped count as one edit.
  EXPECT_EQ(hystbench("lsit").output, "hystbench: error: unknown command 'lsit'; did you mean "
                                      "'list'? (hystbench --help lists the commands)\n");
  const auto far = hystbench("frobnicate");
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.output,
            "hystbench: error: unknown command 'frobnicate' (hystbench --help lists the commands)\n");
  const auto none = hystbench("");
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.output, "hystbench: error: no command given (hystbench --help lists the commands)\n");
}

// CLI11's own range check printed an open bound as a 309-digit number.
TEST_F(Cli, OutOfRangeNumberSaysWhatIsAllowed) {
  const fs::path out = dir_ / "fit";
  const auto o = hystbench("fit --data " + default_data() + " --model msd --evaluations -5 --out " +
                           out.string());
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(o.output, "hystbench: error: --evaluations: -5 is not allowed; give a positive number "
                      "of evaluations (0 = default)\n");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(hystbench("simulate --params p.json --excitation e.json --noise 11 --out x.csv").output,
            "hystbench: error: --noise: 11 is not allowed; give a fraction of the output RMS from "
            "0 to 10\n");
  // --help gives the bounds as people write them.
  const auto help = hystbench("fit --help");
  EXPECT_NE(help.output.find("--evaluations INT:0 or more"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("0 to 1000"), std::string::npos) << help.output;
  EXPECT_EQ(help.output.find("1.79769"), std::string::npos) << help.output;
}

}  // namespace
