// The discovery commands as a user runs them: simulate a measurement with a
// hidden effect, fit, compare, diagnose, discover; reruns that reproduce
// bit for bit; bad input answered with one clear message and exit 2.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tests/run_command.hpp"
#include "tests/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

using hystbench::test_support::Outcome;

// The discovery commands, run like the others.
Outcome run(const std::string& args) { return hystbench::test_support::hystbench(args); }

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(std::ifstream(p)); }

int count(const std::string& text, const std::string& part) {
  int n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
  return n;
}

// Digits of a printed number from its first non-zero one, exponent aside:
// "0.01235" and "1.235e-05" have 4.
int significant_digits(const std::string& printed) {
  std::string digits;
  for (char c : printed.substr(0, printed.find_first_of("eE")))
    if (std::isdigit(static_cast<unsigned char>(c)) && (c != '0' || !digits.empty())) digits += c;
  return int(digits.size());
}

// Data from `msd` with a sensor offset of 2 µm hidden in it: 2.4 s at 500 Hz.
class DiscoveryCli : public ::testing::Test {
 protected:
  void SetUp() override {
    temp_.write("exc.json", R"({"sample_rate": 500, "segments": [
        {"type": "sine", "frequency": 2, "amplitude": 50, "duration": 0.6},
        {"type": "sine", "frequency": 6, "amplitude": 60, "duration": 0.6},
        {"type": "sine", "frequency": 15, "amplitude": 40, "duration": 0.6},
        {"type": "sine", "frequency": 30, "amplitude": 50, "duration": 0.6}]})");
    temp_.write("truth.json", R"({"gain": 0.1, "msd.period": 0.03, "msd.zeta": 0.2,
                                  "offset.c0": 2.0})");
    const auto s = run("simulate --model msd,offset --params " + path("truth.json") +
                       " --excitation " + path("exc.json") +
                       " --noise 0.01 --seed 4 --input-unit V --output-unit µm --out " +
                       path("data.csv"));
    ASSERT_EQ(s.code, 0) << s.output;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static constexpr const char* kQuick = " --evaluations 3000 --restarts 1 --local-evaluations 600";

  hystbench::test_support::TempDir temp_;
  const fs::path& dir_ = temp_.path();
};

TEST_F(DiscoveryCli, FitWritesNamedPhysicalParametersAndReproduces) {
  const auto a = run("fit --data " + path("data.csv") + " --model msd,offset --out " + path("a") + kQuick);
  ASSERT_EQ(a.code, 0) << a.output;
  const auto b = run("fit --data " + path("data.csv") + " --model msd,offset --out " + path("b") + kQuick);
  ASSERT_EQ(b.code, 0) << b.output;
  const auto fa = read_json(dir_ / "a" / "fit.json"), fb = read_json(dir_ / "b" / "fit.json");
  EXPECT_EQ(fa["parameters"], fb["parameters"]);
  EXPECT_EQ(fa["model"], "msd,offset");
  EXPECT_EQ(fa["seed"], 1);
  ASSERT_TRUE(fa["metrics"].contains("heldout"));
  for (const auto& p : fa["parameters"])
    if (p["name"] == "offset.c0") {
      EXPECT_EQ(p["unit"], "µm");
      EXPECT_NEAR(p["value"].get<double>(), 2.0, 0.1);
    }
  // The fit's own numbers say where it came from.
  EXPECT_TRUE(fa["provenance"].contains("git_commit"));
}

TEST_F(DiscoveryCli, CompareWritesMetricsReportAndFigures) {
  ASSERT_EQ(run("fit --data " + path("data.csv") + " --model msd --out " + path("f") + kQuick).code, 0);
  const auto c = run("compare --data " + path("data.csv") + " --fit " + path("f/fit.json") +
                     " --out " + path("c"));
  ASSERT_EQ(c.code, 0) << c.output;
  const auto m = read_json(dir_ / "c" / "metrics.json");
  for (const char* key : {"estimation", "heldout", "by_segment", "by_amplitude", "by_branch",
                          "by_time", "residual", "noise_floor", "signatures"})
    EXPECT_TRUE(m.contains(key)) << key;
  EXPECT_TRUE(fs::exists(dir_ / "c" / "report.md"));
  EXPECT_TRUE(fs::exists(dir_ / "c" / "residual.gp"));
  // A model without the offset leaves a residual with a clearly non-zero mean.
  EXPECT_GT(std::abs(m["residual"]["mean"].get<double>()), 1.0);

  // The terminal shows four significant digits and the unit; the file keeps every digit.
  for (const char* part : {"estimation", "heldout"}) {
    const std::regex line(std::string("  ") + part + R"(: RMSE (\S+) µm, fit (\S+) %, (\d+) samples)");
    std::smatch found;
    ASSERT_TRUE(std::regex_search(c.output, found, line)) << c.output;
    for (int i : {1, 2}) {
      const std::string printed = found[i];
      const double full = m[part][i == 1 ? "rmse" : "fit_percent"].get<double>();
      EXPECT_NEAR(std::stod(printed), full, 5e-4 * std::abs(full)) << printed;
      EXPECT_LE(significant_digits(printed), 4) << printed;
    }
    EXPECT_EQ(std::stol(found[3]), m[part]["n"].get<long>());
  }
  const std::regex sigma(R"(  estimated noise sigma (\S+) µm \(RMSE / sigma (\S+)\))");
  std::smatch found;
  ASSERT_TRUE(std::regex_search(c.output, found, sigma)) << c.output;
  EXPECT_NEAR(std::stod(found[1]), m["noise_floor"]["sigma"].get<double>(),
              5e-4 * m["noise_floor"]["sigma"].get<double>());

  // Seven samples are too few for a noise estimate: the terminal says why, never "null".
  std::string few = "t,u,y\n";
  for (int k = 0; k < 7; ++k) few += std::to_string(k * 0.002) + ",1,0.1\n";
  temp_.write("few.csv", few);
  const auto short_compare = run("compare --data " + path("few.csv") + " --fit " +
                                 path("f/fit.json") + " --out " + path("few"));
  ASSERT_EQ(short_compare.code, 0) << short_compare.output;
  EXPECT_NE(short_compare.output.find("  noise sigma not estimated (fewer than 8 samples)\n"),
            std::string::npos)
      << short_compare.output;
  EXPECT_EQ(short_compare.output.find("null"), std::string::npos) << short_compare.output;
  EXPECT_NE(short_compare.output.find("fit % not defined (y is constant)"), std::string::npos)
      << short_compare.output;
}

// On a record the model was not fitted on, every sample is a test sample:
// the report says so instead of calling them estimation samples.
TEST_F(DiscoveryCli, CompareOnAnotherRecordCallsItATest) {
  ASSERT_EQ(run("fit --data " + path("data.csv") + " --model msd --holdout none --out " + path("f") + kQuick).code, 0);
  fs::copy_file(dir_ / "data.csv", dir_ / "other.csv");
  const auto report_of = [&](const std::string& data, const std::string& out) {
    const auto c = run("compare --data " + path(data) + " --fit " + path("f/fit.json") + " --out " + path(out));
    EXPECT_EQ(c.code, 0) << c.output;
    return hystbench::test_support::read(dir_ / out / "report.md");
  };
  const std::string own = report_of("data.csv", "own"), other = report_of("other.csv", "other");
  const std::string test_sentence = "The model was fitted on another record: every number is a test score.";
  EXPECT_NE(own.find("| estimation | "), std::string::npos) << own;
  EXPECT_NE(own.find("every number is on estimation data"), std::string::npos) << own;
  EXPECT_EQ(own.find(test_sentence), std::string::npos) << own;
  EXPECT_NE(other.find("| test | "), std::string::npos) << other;
  EXPECT_NE(other.find(test_sentence), std::string::npos) << other;
  EXPECT_EQ(other.find("estimation"), std::string::npos) << other;
}

// A record caught mid-motion: fit names the ringing a model started at rest
// cannot follow and the warm-up that removes it, and says nothing once fitted
// with that warm-up (docs/discovery.md, "Start-up transients").
TEST_F(DiscoveryCli, FitNamesAStartUpTransientAndTheWarmUpThatRemovesIt) {
  {
    // 4 s at 500 Hz of a 2 Hz sine through a gain of 0.1, a 97 Hz tone no
    // model here follows as the error floor, and a 40 Hz ringing that decays
    // by e every 100 samples from the first sample.
    std::ofstream csv(dir_ / "ringing.csv");
    csv << "t,u,y\n";
    for (int k = 0; k < 2000; ++k) {
      const double t = k / 500.0, u = 50.0 * std::sin(2 * M_PI * 2.0 * t);
      const double y = 0.1 * u + 0.05 * std::sin(2 * M_PI * 97.0 * t) +
                       30.0 * std::exp(-k / 100.0) * std::sin(2 * M_PI * 40.0 * t);
      csv << t << ',' << u << ',' << y << '\n';
    }
  }
  const std::string fit = "fit --data " + path("ringing.csv") + " --model msd --holdout none --force" + kQuick;
  const auto ringing = run(fit + " --out " + path("r"));
  ASSERT_EQ(ringing.code, 0) << ringing.output;
  const std::regex advice("A start-up transient dominates the error[^\n]*--warmup ([0-9]+) \\(where the error");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(ringing.output, m, advice)) << ringing.output;
  // The ringing's RMS, 21.2 e^(-k/100), falls below twice the floor's
  // (2 * 0.05 / sqrt(2)) after 100 ln(21.2 / 0.07) = 571 samples; blocks of
  // half the 250-sample period put the advice at the next block, 625. One
  // period, the old advice, would be 250.
  const int warmup = std::stoi(m[1]);
  EXPECT_GE(warmup, 500) << ringing.output;
  EXPECT_LE(warmup, 750) << ringing.output;
  const auto settled = run(fit + " --warmup " + std::to_string(warmup) + " --out " + path("s"));
  ASSERT_EQ(settled.code, 0) << settled.output;
  EXPECT_EQ(settled.output.find("start-up transient"), std::string::npos) << settled.output;
}

TEST_F(DiscoveryCli, DiagnoseNamesTheHiddenOffsetAndDiscoverAddsIt) {
  const auto d = run("diagnose --data " + path("data.csv") + " --model msd --out " + path("d") +
                     " --candidates offset,drift,delay" + kQuick);
  ASSERT_EQ(d.code, 0) << d.output;
  const auto j = read_json(dir_ / "d" / "diagnosis.json");
  EXPECT_EQ(j["verdict"], "offset");
  EXPECT_EQ(j["candidates"][0]["effect"], "offset");
  for (const char* key : {"delta_bic", "rmse_before", "rmse_after", "heldout_rmse_before",
                          "heldout_rmse_after", "evidence"})
    EXPECT_TRUE(j["candidates"][0].contains(key)) << key;
  EXPECT_TRUE(j.contains("where"));
  EXPECT_TRUE(fs::exists(dir_ / "d" / "extended_fit.json"));
  EXPECT_NE(d.output.find("verdict: offset"), std::string::npos);
  // The report names the worst branch (its loop once read a destroyed
  // temporary, which AddressSanitizer caught).
  const std::string text = hystbench::test_support::read(dir_ / "d" / "report.md");
  EXPECT_NE(text.find("- worst branch: "), std::string::npos) << text;

  const auto l = run("discover --data " + path("data.csv") + " --start msd --out " + path("l") +
                     " --candidates offset,drift,delay" + kQuick);
  ASSERT_EQ(l.code, 0) << l.output;
  const auto ladder = read_json(dir_ / "l" / "ladder.json");
  EXPECT_EQ(ladder["final_effects"], nlohmann::json({"msd", "offset"}));
  EXPECT_EQ(ladder["steps"].size(), 2u);
  EXPECT_EQ(ladder["steps"][1]["added"], "offset");
  const double sd = read_json(dir_ / "data.truth.json")["noise"]["sd"];
  EXPECT_LT(ladder["steps"][1]["heldout_rmse"].get<double>(), 1.2 * sd);
  EXPECT_TRUE(fs::exists(dir_ / "l" / "ladder.md"));
  EXPECT_TRUE(fs::exists(dir_ / "l" / "ladder.gp"));
}

// A diagnose run of the start model is discover's first rung: started from
// it, discover climbs the same ladder without diagnosing the start again,
// and a diagnosis or stopped run made with other options is refused naming
// the option.
TEST_F(DiscoveryCli, DiscoverFromADiagnosisClimbsTheSameLadder) {
  const std::string common = " --data " + path("data.csv") + " --candidates offset,drift,delay" + kQuick;
  const auto d = run("diagnose --model msd --out " + path("d") + common);
  ASSERT_EQ(d.code, 0) << d.output;
  ASSERT_TRUE(fs::exists(dir_ / "d" / "checkpoint.json"));
  const auto whole = run("discover --start msd --out " + path("whole") + common);
  ASSERT_EQ(whole.code, 0) << whole.output;
  const auto from = run("discover --start msd --diagnosis " + path("d") + " --out " + path("from") + common);
  ASSERT_EQ(from.code, 0) << from.output;
  EXPECT_NE(from.output.find("from " + path("d") + ", step 0: msd"), std::string::npos) << from.output;
  EXPECT_EQ(count(from.output, "step 0"), 1) << "the start model was diagnosed again:\n" << from.output;
  auto a = read_json(dir_ / "whole" / "ladder.json"), b = read_json(dir_ / "from" / "ladder.json");
  a.erase("provenance");
  b.erase("provenance");
  EXPECT_EQ(a.dump(), b.dump());
  EXPECT_EQ(read_json(dir_ / "from" / "step_0" / "diagnosis.json")["verdict"], "offset");
  EXPECT_TRUE(fs::exists(dir_ / "from" / "step_0" / "report.md"));
  EXPECT_EQ(b["final_effects"], nlohmann::json({"msd", "offset"}));

  const auto other = run("discover --start msd --seed 2 --diagnosis " + path("d") + " --out " + path("o") + common);
  EXPECT_EQ(other.code, 2) << other.output;
  EXPECT_NE(other.output.find("was made with another options."), std::string::npos) << other.output;
  EXPECT_NE(other.output.find("fit.seed"), std::string::npos) << other.output;
  EXPECT_FALSE(fs::exists(dir_ / "o")) << "a refused rung must leave nothing behind";
  const auto start = run("discover --start none --diagnosis " + path("d") + " --out " + path("o") + common);
  EXPECT_EQ(start.code, 2) << start.output;
  EXPECT_NE(start.output.find("another options.start"), std::string::npos) << start.output;
  // A ladder is climbed under one input hold: neither a diagnosis nor a
  // stopped run made under the spline is continued under another.
  const auto hold = run("discover --start msd --input-hold bandlimited --diagnosis " + path("d") + " --out " +
                        path("o") + common);
  EXPECT_EQ(hold.code, 2) << hold.output;
  EXPECT_NE(hold.output.find("was made with another options.input_hold"), std::string::npos) << hold.output;
  const auto resumed = run("discover --start msd --resume --input-hold bandlimited --out " + path("from") + common);
  EXPECT_EQ(resumed.code, 2) << resumed.output;
  EXPECT_NE(resumed.output.find("was made with another options.input_hold; resume with the same data and options"),
            std::string::npos)
      << resumed.output;
  auto after = read_json(dir_ / "from" / "ladder.json");
  after.erase("provenance");
  EXPECT_EQ(after.dump(), b.dump()) << "a refused resume must not touch the run";
  const auto both = run("discover --start msd --resume --diagnosis " + path("d") + " --out " + path("o") + common);
  EXPECT_EQ(both.code, 2) << both.output;
  EXPECT_NE(both.output.find("not both"), std::string::npos) << both.output;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
}

// A start model that is already the last rung: with only `delay` to try,
// nothing captures the hidden offset, and the diagnosis says the rest is
// beyond the catalog. Started from it, discover must end with the same
// verdict and reason, which were judged on candidates a rung does not keep.
TEST_F(DiscoveryCli, DiscoverFromALastRungKeepsItsBeyondCatalogVerdict) {
  const std::string common = " --data " + path("data.csv") + " --candidates delay" + kQuick;
  const auto d = run("diagnose --model msd --out " + path("d") + common);
  ASSERT_EQ(d.code, 0) << d.output;
  const auto whole = run("discover --start msd --out " + path("whole") + common);
  ASSERT_EQ(whole.code, 0) << whole.output;
  const auto from = run("discover --start msd --diagnosis " + path("d") + " --out " + path("from") + common);
  ASSERT_EQ(from.code, 0) << from.output;
  auto a = read_json(dir_ / "whole" / "ladder.json"), b = read_json(dir_ / "from" / "ladder.json");
  ASSERT_EQ(a["completeness"]["kind"], "beyond_catalog") << a["completeness"].dump();
  a.erase("provenance");
  b.erase("provenance");
  EXPECT_EQ(a.dump(), b.dump());
  EXPECT_EQ(hystbench::test_support::read(dir_ / "whole" / "ladder.md"),
            hystbench::test_support::read(dir_ / "from" / "ladder.md"));
}

TEST_F(DiscoveryCli, AWarmUpIsNeverScoredAndTravelsWithTheFit) {
  // 1 200 samples; the first 100 only initialise the model.
  const auto f = run("fit --data " + path("data.csv") + " --model msd,offset --warmup 100 --out " + path("w") + kQuick);
  ASSERT_EQ(f.code, 0) << f.output;
  const auto fit = read_json(dir_ / "w" / "fit.json");
  EXPECT_EQ(fit["holdout"], "auto+warmup:100");
  const long estimation = fit["errors"]["estimation_samples"], heldout = fit["errors"]["heldout_samples"];
  EXPECT_EQ(estimation + heldout, 1100);
  // compare inherits the warm-up, and its excitation sentence names the sines.
  const auto c = run("compare --data " + path("data.csv") + " --fit " + path("w/fit.json") + " --out " + path("wc"));
  ASSERT_EQ(c.code, 0) << c.output;
  const auto m = read_json(dir_ / "wc" / "metrics.json");
  EXPECT_EQ(m["all"]["n"], 1100);
  EXPECT_EQ(m["excitation"]["tones_hz"].size(), 4u) << m["excitation"].dump();
  EXPECT_NE(c.output.find("The record excites 4 frequencies"), std::string::npos) << c.output;
  // --warmup 0 on the command line scores every sample again.
  const auto all = run("compare --data " + path("data.csv") + " --fit " + path("w/fit.json") + " --warmup 0 --out " +
                       path("wa"));
  ASSERT_EQ(all.code, 0) << all.output;
  EXPECT_EQ(read_json(dir_ / "wa" / "metrics.json")["all"]["n"], 1200);
  // A warm-up as long as the record leaves nothing to score.
  const auto bad = run("fit --data " + path("data.csv") + " --model msd --warmup 1200 --out " + path("wb"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("--warmup 1200: the record has only 1200 samples"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir_ / "wb" / "fit.json"));
}

TEST_F(DiscoveryCli, AHeldStartTravelsWithTheFitAndNeedsAWarmUp) {
  const auto f = run("fit --data " + path("data.csv") + " --model msd,offset --warmup 20 --initial-state held --out " +
                     path("h") + kQuick);
  ASSERT_EQ(f.code, 0) << f.output;
  EXPECT_EQ(read_json(dir_ / "h" / "fit.json")["holdout"], "auto+warmup:20+held");
  // compare starts any record the same way unless told otherwise.
  const auto c = run("compare --data " + path("data.csv") + " --fit " + path("h/fit.json") + " --out " + path("hc"));
  ASSERT_EQ(c.code, 0) << c.output;
  EXPECT_EQ(read_json(dir_ / "hc" / "metrics.json")["all"]["n"], 1180);
  EXPECT_NE(c.output.find("(started where u held at "), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("leaves it: the level that matches the first 20 samples)"), std::string::npos) << c.output;
  const auto rest = run("compare --data " + path("data.csv") + " --fit " + path("h/fit.json") +
                        " --warmup 0 --out " + path("hr"));
  EXPECT_EQ(rest.code, 2);
  EXPECT_NE(rest.output.find("give --warmup N (N of 1 or more, e.g. 5), or --initial-state rest"), std::string::npos)
      << rest.output;
  EXPECT_FALSE(fs::exists(dir_ / "hr" / "metrics.json"));
  const auto bad = run("fit --data " + path("data.csv") + " --model msd --initial-state held --out " + path("hb"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.output.find("--initial-state held: the held level is matched to the warm-up samples"),
            std::string::npos)
      << bad.output;
  EXPECT_FALSE(fs::exists(dir_ / "hb" / "fit.json"));
}

TEST_F(DiscoveryCli, FitFromAFitStartsThereWithItsSetUpAndIsNeverWorse) {
  const auto a = run("fit --data " + path("data.csv") + " --model msd,offset --warmup 100 --input-hold bandlimited --out " +
                     path("fa") + kQuick);
  ASSERT_EQ(a.code, 0) << a.output;
  const auto start = read_json(dir_ / "fa" / "fit.json");
  // Its model, warm-up and hold come along; a polish alone may only gain.
  const auto r = run("fit --data " + path("data.csv") + " --from " + path("fa/fit.json") + " --restarts 0 --out " +
                     path("fr"));
  ASSERT_EQ(r.code, 0) << r.output;
  const auto again = read_json(dir_ / "fr" / "fit.json");
  EXPECT_EQ(again["model"], "msd,offset");
  EXPECT_EQ(again["holdout"], "auto+warmup:100");
  EXPECT_EQ(again["input_hold"], "bandlimited");
  EXPECT_EQ(again["fit"]["from"], path("fa/fit.json"));
  EXPECT_LE(again["errors"]["rmse"].get<double>(), start["errors"]["rmse"].get<double>());
  // What the command line gives wins.
  const auto s = run("fit --data " + path("data.csv") + " --from " + path("fa/fit.json") +
                     " --input-hold spline --warmup 50 --restarts 0 --out " + path("fs"));
  ASSERT_EQ(s.code, 0) << s.output;
  const auto spline = read_json(dir_ / "fs" / "fit.json");
  EXPECT_EQ(spline.value("input_hold", "spline"), "spline");
  EXPECT_EQ(spline["holdout"], "auto+warmup:50");
  // Another model, or none at all, is refused before anything is written.
  const auto other = run("fit --data " + path("data.csv") + " --from " + path("fa/fit.json") + " --model msd --out " +
                         path("fo"));
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.output.find("--model msd is not the model of --from"), std::string::npos) << other.output;
  EXPECT_FALSE(fs::exists(dir_ / "fo" / "fit.json"));
  const auto none = run("fit --data " + path("data.csv") + " --out " + path("fn"));
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.output.find("give --model LIST, or --from FIT.json"), std::string::npos) << none.output;
  EXPECT_FALSE(fs::exists(dir_ / "fn" / "fit.json"));
}

// A fit made with coarse sub-steps is diagnosed as it was fitted: without
// --substeps the diagnosis is the one that names the fit's own count.
TEST_F(DiscoveryCli, DiagnoseOfAFitKeepsItsSubSteps) {
  const auto f = run("fit --data " + path("data.csv") + " --model duffing,offset --substeps 1 --out " + path("c") + kQuick);
  ASSERT_EQ(f.code, 0) << f.output;
  const auto diagnosed = [&](const std::string& dir, const std::string& extra) {
    const auto d = run("diagnose --data " + path("data.csv") + " --fit " + path("c/fit.json") +
                       " --candidates drift --out " + path(dir) + kQuick + extra);
    EXPECT_EQ(d.code, 0) << d.output;
    return read_json(dir_ / dir / "diagnosis.json")["candidates"][0]["rmse_before"].get<double>();
  };
  const double kept = diagnosed("cd", ""), one = diagnosed("c1", " --substeps 1"),
               fine = diagnosed("c20", " --substeps 20");
  EXPECT_EQ(kept, one);
  EXPECT_NE(kept, fine);
}

TEST_F(DiscoveryCli, BadInputGetsOneMessageAndExitTwo) {
  auto r = run("fit --data " + path("data.csv") + " --model msd,creeep --out " + path("x"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("creeep"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("creep"), std::string::npos) << "names the catalog: " << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "x" / "fit.json"));

  r = run("diagnose --data " + path("data.csv") + " --out " + path("y"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("either --model LIST"), std::string::npos) << r.output;

  r = run("compare --data " + path("data.csv") + " --fit " + path("truth.json") + " --out " + path("z"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("not a fit file"), std::string::npos) << r.output;

  r = run("fit --data " + path("data.csv") + " --model msd --holdout half --out " + path("w"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("last:FRACTION"), std::string::npos) << r.output;

  r = run("fit --data " + path("data.csv") + " --model msd --optimizer nope --out " + path("v"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("jso"), std::string::npos) << "names the optimizers: " << r.output;

  // propose given a folder that is no discover folder.
  fs::create_directories(dir_ / "not_a_ladder");
  r = run("propose --data " + path("data.csv") + " --fit " + path("not_a_ladder") + " --out " + path("u"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("a folder without ladder.json"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "u"));
}

}  // namespace
